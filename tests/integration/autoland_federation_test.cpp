// The ILS approach and autoland deployment (the README's, deploy/ils-autoland.yaml) as a user
// runs it: real federates over DDS on 127.0.0.1 in lockstep, and the same file composed
// in-process. Its own executable: a 20,000-frame federation is run serially, with a longer
// timeout than the other integration tests.
#include "common/util/child_process.hpp"
#include "common/util/build_paths.hpp"
#include "common/runtime/topic_types.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <map>
#include <sstream>
#include <string>
#include <vector>

namespace fedsim::testing {
namespace {

using util::ChildProcess;
using util::read_file;
using util::temp_dir;

std::string bin(const std::string& name) { return fedsim::util::bin_dir() + "/" + name; }

/// The value of `column` in the last row of a recorded CSV (fedsim record's header names).
double last_value(const std::string& csv, const std::string& column) {
  auto split = [](const std::string& line) {
    std::vector<std::string> cells;
    std::stringstream in(line);
    for (std::string cell; std::getline(in, cell, ',');) cells.push_back(cell);
    return cells;
  };
  std::stringstream in(csv);
  std::string header, line, last;
  std::getline(in, header);
  while (std::getline(in, line)) {
    if (!line.empty()) last = line;
  }
  const auto names = split(header), cells = split(last);
  for (std::size_t i = 0; i < names.size() && i < cells.size(); ++i) {
    if (names[i] == column) return std::stod(cells[i]);
  }
  ADD_FAILURE() << "no column " << column;
  return std::nan("");
}

// The ILS approach and autoland deployment (the README's main job): over DDS in lockstep the 737
// lands and stops under the autopilot, and the in-process composition of the same file computes
// the same recording (and the same pictures at the decision height) byte for byte.
TEST(Federation, IlsAutolandDeploymentLandsAndMatchesTheInProcessRun) {
  const std::string dir = temp_dir("ils_autoland");
  const std::string yaml = fedsim::util::source_dir() + "/deploy/ils-autoland.yaml";
  std::map<std::string, std::string> progress;  // fedsim run's output per run
  auto fly = [&](const std::string& name, std::vector<std::string> extra) {
    const std::string out = dir + "/" + name;
    std::vector<std::string> argv = {bin("fedsim"), "run", yaml, "--out", out, "--quiet", "--progress", "2"};
    argv.insert(argv.end(), extra.begin(), extra.end());
    ChildProcess fedsim(argv, dir + "/" + name + ".log");
    EXPECT_TRUE(fedsim.wait(300)) << fedsim.output();
    EXPECT_EQ(fedsim.exit_code(), 0) << fedsim.output();
    EXPECT_TRUE(std::filesystem::exists(out + "/ils_autoland.png")) << fedsim.output();
    progress[name] = fedsim.output();
    return std::pair{read_file(out + "/fedsim_aircraft_state.csv"), read_file(out + "/fedsim_autopilot_state.csv")};
  };
  const auto [dds_aircraft, dds_autopilot] = fly("dds", {"--domain", "197"});  // a domain no other test uses (ctest -j runs them side by side)
  // The progress lines the README shows: the flight federate's phase of flight, distance to go
  // and modes (the glide slope lasts about 40 % of the run, the stop the last 12 %).
  EXPECT_NE(progress["dds"].find("\n    flight: glide slope: "), std::string::npos) << progress["dds"];
  EXPECT_NE(progress["dds"].find(" NM to the threshold, "), std::string::npos);
  EXPECT_NE(progress["dds"].find("| MCP SPD | VOR/LOC | G/S"), std::string::npos);
  EXPECT_NE(progress["dds"].find("flight: stopped: "), std::string::npos);
  const auto [local_aircraft, local_autopilot] = fly("in_process", {"--in-process"});
  EXPECT_EQ(std::count(dds_autopilot.begin(), dds_autopilot.end(), '\n'), 20001);  // header + every frame
  // Landed, stopped, the autopilot still engaged in ROLLOUT with no alert, the levers at idle.
  EXPECT_EQ(last_value(dds_autopilot, "fma.roll"), static_cast<double>(msg::FMA_ROLL_ROLLOUT));
  EXPECT_EQ(last_value(dds_autopilot, "fma.pitch"), static_cast<double>(msg::FMA_PITCH_ROLLOUT));
  EXPECT_EQ(last_value(dds_autopilot, "fma.autopilot_engaged"), 1.0);
  EXPECT_EQ(last_value(dds_autopilot, "fma.alerts"), 0.0);
  EXPECT_EQ(last_value(dds_aircraft, "on_ground"), 1.0);
  EXPECT_LT(last_value(dds_aircraft, "ground_speed_mps"), 0.5);
  EXPECT_LT(last_value(dds_aircraft, "controls.throttle[0]"), 0.05);
  EXPECT_TRUE(dds_aircraft == local_aircraft) << "the in-process composition flew a different aircraft";
  EXPECT_TRUE(dds_autopilot == local_autopilot) << "the in-process autopilot differs from the federation's";
  // The motion platform cued the whole flight without a cut-off.
  const std::string dds_motion = read_file(dir + "/dds/fedsim_motion_state.csv");
  EXPECT_EQ(std::count(dds_motion.begin(), dds_motion.end(), '\n'), 20001);
  EXPECT_EQ(last_value(dds_motion, "status"), static_cast<double>(msg::MOTION_ENGAGED));
  EXPECT_TRUE(dds_motion == read_file(dir + "/in_process/fedsim_motion_state.csv"));
  // The control loader felt the controls the whole flight, back-driven by the autopilot.
  const std::string dds_loading = read_file(dir + "/dds/fedsim_control_loading_state.csv");
  EXPECT_EQ(std::count(dds_loading.begin(), dds_loading.end(), '\n'), 20001);
  EXPECT_EQ(last_value(dds_loading, "status"), static_cast<double>(msg::CONTROL_LOADING_ACTIVE));
  EXPECT_EQ(last_value(dds_loading, "pitch_backdriven"), 1.0);
  EXPECT_EQ(last_value(dds_loading, "stick_shaker"), 0.0);  // inhibited on the ground
  EXPECT_TRUE(dds_loading == read_file(dir + "/in_process/fedsim_control_loading_state.csv"));
  // The three channels at the decision height, stitched; each channel's picture is drawn from
  // the same state in both runs, so the pictures are the same bytes.
  EXPECT_TRUE(std::filesystem::exists(dir + "/dds/decision_height.png"));
  for (const char* channel : {"left", "centre", "right"}) {
    const std::string name = std::string("/dh_") + channel + ".png";
    EXPECT_TRUE(read_file(dir + "/dds" + name) == read_file(dir + "/in_process" + name)) << name;
  }
  // The QTG report of the run (the last after-step: the recording against the autoland criteria;
  // a failed check would have failed the run).
  EXPECT_TRUE(std::filesystem::exists(dir + "/dds/qtg/qtg_report.html"));
  EXPECT_NE(read_file(dir + "/dds/qtg/qtg_report.html").find("1 of 1 tests passed"), std::string::npos);
  // The cockpit displays' last pictures.
  EXPECT_TRUE(std::filesystem::exists(dir + "/dds/pfd.png"));
  EXPECT_TRUE(std::filesystem::exists(dir + "/dds/nd.png"));
}

}  // namespace
}  // namespace fedsim::testing
