// The station's replay of a recording over DDS (loopback, its own domain): a recording made by
// the in-process recorder is read back and published on fedsim/replay_state, every sample equal
// to the one recorded (but for the frame stamp, which the station sets); a name that is not a
// listed recording is refused, as is a bad request.
#include "ios/station_replay.hpp"

#include "common/runtime/composition.hpp"
#include "common/runtime/federate_options.hpp"
#include "common/util/wait_until.hpp"
#include "tools/topic/in_process_recorder.hpp"

#include <gtest/gtest.h>

#include <chrono>
#include <cmath>
#include <filesystem>
#include <mutex>
#include <thread>

namespace fedsim::ios {
namespace {

namespace fs = std::filesystem;

/// An aircraft whose every field moves with the frame (so a mix-up of samples shows).
class Moving final : public runtime::Component {
 public:
  Moving() : Component("flight"), out_(writes(runtime::topics::aircraft_state)) {}
  void step(const runtime::FrameContext& frame) override {
    const double t = frame.end_time_s();
    msg::AircraftState s;
    s.latitude_rad(0.6 + 1e-6 * t);
    s.longitude_rad(-2.1 - 2e-6 * t);
    s.altitude_msl_m(1000.0 + 0.123456789 * t);
    s.velocity_ned_mps({1.0 / 3.0, 50.0 + t, -0.25});
    s.psi_rad(0.1 * t);
    s.air().tas_mps(51.0 + 0.001 * t);
    s.stamp(frame.end_stamp());
    out_.write(s);
  }

 private:
  runtime::Output<msg::AircraftState>& out_;
};

fs::path make_recording() {
  const fs::path dir = fs::path(testing::TempDir()) / "station_replay_recordings" / "flight1";
  fs::remove_all(dir.parent_path());
  Moving aircraft;
  runtime::Composition composition({});
  composition.add(aircraft);
  {
    tools::InProcessRecorder recorder(composition, {"fedsim/aircraft_state"}, dir);
    composition.run(100);  // 2 s at 50 Hz
    recorder.close();
  }
  return dir;
}

TEST(StationReplay, ARecordingIsPublishedBackSampleForSample) {
  const fs::path dir = make_recording();
  runtime::ParticipantOptions dds_options;
  dds_options.domain_id = 153;
  dds_options.name = "station_replay_test";
  dds_options.qos_file = runtime::default_qos_file();
  auto dds = runtime::DdsParticipant::create(dds_options);
  std::mutex mutex;
  std::vector<msg::AircraftState> received;
  runtime::Subscription<msg::AircraftState> reader(
      dds, runtime::topics::replay_state, runtime::qos::kState, [&](const msg::AircraftState& s, const auto&) {
        std::lock_guard lock(mutex);
        received.push_back(s);
      });
  std::uint64_t frame = 5000;
  StationReplay replay(dds, 60.0, dir.parent_path(), [&] { return frame; });
  EXPECT_EQ(replay.recordings(), std::vector<std::string>{"flight1"});
  EXPECT_THROW(replay.request({{"action", "start"}, {"source", "recording"}, {"name", "../flight1"}}),
               std::invalid_argument);
  EXPECT_THROW(replay.request({{"action", "start"}, {"source", "recording"}, {"name", "flight1"}, {"speed", 0}}),
               std::invalid_argument);
  EXPECT_THROW(replay.request({{"action", "jump"}}), std::invalid_argument);
  ASSERT_TRUE(reader.wait_for_writers(1, std::chrono::seconds(5)));  // no sample lost to discovery
  const auto started = replay.request({{"action", "start"}, {"source", "recording"}, {"name", "flight1"}, {"speed", 2}});
  EXPECT_EQ(started["samples"], 100);
  EXPECT_TRUE(started["active"].get<bool>());
  // 2 s of recording at 2x: one second, then the last sample held.
  ASSERT_TRUE(util::wait_until([&] {
    std::lock_guard lock(mutex);
    return !received.empty() && std::abs(received.back().altitude_msl_m() - (1000.0 + 0.123456789 * 2.0)) < 1e-12;
  }, 30)) << "the last sample did not arrive";
  replay.stop();
  std::lock_guard lock(mutex);
  // Every sample that arrived is one of the recorded ones, exactly (the sample of frame k has
  // altitude 1000 + 0.123456789 * 0.02 (k + 1)), in order; the stamp is the station's frame.
  double last_t = -1.0;
  for (const auto& s : received) {
    const double t = (s.altitude_msl_m() - 1000.0) / 0.123456789;
    const double k = std::round(t / 0.02);
    ASSERT_NEAR(t, 0.02 * k, 1e-9);
    ASSERT_GE(t, last_t);
    last_t = t;
    EXPECT_EQ(s.velocity_ned_mps()[1], 50.0 + 0.02 * k);
    EXPECT_EQ(s.velocity_ned_mps()[0], 1.0 / 3.0);
    EXPECT_EQ(s.air().tas_mps(), 51.0 + 0.001 * (0.02 * k));
    EXPECT_EQ(s.stamp().frame(), 5000u);
  }
  EXPECT_GT(received.size(), 50u);  // most of the 100 (best effort, a sample per 5 ms at most)
}

}  // namespace
}  // namespace fedsim::ios
