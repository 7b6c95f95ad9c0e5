// The instructor station's flight-data replay (seed 9.7):
//   - a ring buffer of the live aircraft state, the last --ring-minutes of it (every sample the
//     flight federate writes, not the page's few a second), for "replay the last N minutes";
//   - a recording made by `fedsim record` (any folder under --recordings with a
//     fedsim_aircraft_state.csv), read back exactly (tools/topic/topic_replay);
//   - the replay itself: those states published on fedsim/replay_state, paced by
//     ios/model/replay_clock (speed, pause, seek), which the flight federate writes as the
//     aircraft's state while they arrive (so the map, plots, navigation, visual channels and
//     motion all show it), and "take control from here": the replay stops and the flight
//     federate flies on from the last replayed state.
// Threads: the ring is fed on a DDS listener thread, the replay publishes from its own thread,
// the page's requests come on the server's: every member is guarded. Times are the monotonic
// clock's, taken here.
#pragma once

#include "common/runtime/dds_participant.hpp"
#include "common/runtime/publisher.hpp"
#include "common/runtime/subscription.hpp"
#include "ios/model/replay_clock.hpp"

#include <nlohmann/json.hpp>

#include <atomic>
#include <deque>
#include <filesystem>
#include <functional>
#include <memory>
#include <mutex>
#include <optional>
#include <string>
#include <thread>
#include <vector>

namespace fedsim::ios {

class StationReplay {
 public:
  /// `ring_s`: how much live state the ring keeps [s]; `recordings`: the folder whose
  /// sub-folders (and itself) may be replayed.
  /// `current_frame`: the newest frame tick the station saw. Each replayed sample is stamped with
  /// it, so that a reader that takes frame-stamped samples in order (the flight federate's port)
  /// sees every one as new, wherever the recording's own frame numbers stood.
  StationReplay(std::shared_ptr<runtime::DdsParticipant> dds, double ring_s, std::filesystem::path recordings,
                std::function<std::uint64_t()> current_frame);
  ~StationReplay();
  StationReplay(const StationReplay&) = delete;
  StationReplay& operator=(const StationReplay&) = delete;

  /// A page's request: {"action": "start", "source": "ring", "last_s": 120, "speed": 1} |
  /// {"action": "start", "source": "recording", "name": "default", "speed": 2} | "pause" |
  /// "resume" | {"action": "seek", "t_s": 42.0} | {"action": "speed", "speed": 4} |
  /// "take_control". Returns the replay's state, or throws std::invalid_argument naming the
  /// field.
  nlohmann::json request(const nlohmann::json& body);
  /// {"active", "source", "playing", "speed", "position_s", "start_s", "end_s", "samples",
  ///  "ring_s" (live state held), "recordings": [names]}
  nlohmann::json state() const;
  /// The recordings that can be replayed (folder names relative to --recordings; "." itself).
  std::vector<std::string> recordings() const;
  /// Stops publishing (the flight federate then takes control) and joins the thread.
  void stop();

 private:
  struct Sample {
    double time_s;
    msg::AircraftState state;
  };
  void take_live(const msg::AircraftState& s);
  std::vector<Sample> from_ring(double last_s) const;
  std::vector<Sample> from_recording(const std::string& name) const;
  void start(std::vector<Sample> samples, const std::string& source, double speed);
  void publish_loop();

  std::filesystem::path recordings_;
  double ring_s_;
  std::function<std::uint64_t()> current_frame_;
  mutable std::mutex mutex_;
  std::deque<Sample> ring_;
  std::vector<Sample> samples_;  // the replay's
  std::optional<ReplayClock> clock_;
  std::string source_;
  std::size_t published_index_ = static_cast<std::size_t>(-1);
  std::uint64_t published_ = 0;
  std::atomic<bool> active_{false};
  std::atomic<bool> stopping_{false};
  std::unique_ptr<runtime::Publisher<msg::AircraftState>> writer_;
  std::unique_ptr<runtime::Subscription<msg::AircraftState>> live_;
  std::thread thread_;
};

}  // namespace fedsim::ios
