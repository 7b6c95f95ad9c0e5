// The station's scenario runner: only listed files, their errors by line, a frame skipped (not
// waited for) while the registry is busy and caught up in the next, what fired listed.
#include "ios/station_scenario.hpp"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

namespace fedsim::ios {
namespace {

namespace fs = std::filesystem;

fs::path folder_with(const std::string& good, const std::string& bad) {
  const fs::path dir = fs::path(testing::TempDir()) / "station_scenarios";
  fs::remove_all(dir);
  fs::create_directories(dir);
  std::ofstream(dir / "good.yaml") << good;
  std::ofstream(dir / "bad.yaml") << bad;
  std::ofstream(dir / "notes.txt") << "not a scenario";
  return dir;
}

TEST(StationScenario, RunsAListedFileFrameByFrameWithoutWaiting) {
  StationScenario runner(folder_with(R"(name: t
events:
  - at_s: 1
    do: {command: freeze}
  - when: "fedsim/aircraft_state.height_agl_m < 100 ft"
    do: {log: low}
)",
                                     "name: b\nevents:\n  - at_s: 1\n    do: {command: fail, system: enigne1}\n"));
  EXPECT_EQ(runner.files(), (std::vector<std::string>{"bad.yaml", "good.yaml"}));
  EXPECT_THROW(runner.start("../good.yaml"), std::invalid_argument);
  try {
    runner.start("bad.yaml");
    FAIL() << "a bad file started";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("bad.yaml:4"), std::string::npos) << e.what();
  }
  EXPECT_FALSE(runner.running());
  runner.start("good.yaml");
  ASSERT_TRUE(runner.running());
  double height_m = 20.0;  // below 100 ft (30.5 m)
  const scenario::FieldLookup lookup = [&](const std::string& topic, const std::string& field) -> std::optional<double> {
    if (topic == "fedsim/aircraft_state" && field == "height_agl_m") return height_m;
    return std::nullopt;
  };
  bool registry_free = false;
  const auto step = [&](const auto& run) {
    if (!registry_free) return false;  // busy: skipped, not waited for
    run(lookup);
    return true;
  };
  EXPECT_TRUE(runner.frame(1.00, 0.02, step).empty());  // the registry was busy this frame
  registry_free = true;
  const auto due = runner.frame(1.02, 0.02, step);      // caught up in the next
  ASSERT_EQ(due.size(), 2u);
  EXPECT_EQ(due[0].text, "freeze");
  EXPECT_EQ(due[1].text, "low");
  EXPECT_TRUE(runner.frame(1.04, 0.02, step).empty());  // each fires once
  const auto state = runner.state();
  EXPECT_EQ(state["name"], "good.yaml");
  EXPECT_EQ(state["fired"].size(), 2u) << state.dump();
  EXPECT_EQ(state["fired"][0], "t=1.02 s: freeze");
  runner.stop();
  EXPECT_FALSE(runner.running());
  EXPECT_TRUE(runner.frame(2.0, 0.02, step).empty());
}

}  // namespace
}  // namespace fedsim::ios
