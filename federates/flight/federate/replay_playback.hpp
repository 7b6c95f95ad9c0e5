// Replay through the flight federate (seed 9.7): while recorded aircraft states arrive on
// fedsim/replay_state, the flight federate writes them as its own fedsim/aircraft_state (one
// writer of the aircraft, so the navigation, the motion platform, every display and every
// recorder see the replay, in lockstep too) and leaves its model alone; when they stop for
// kHoldFrames frames, it takes control from the last one: the model is set to that position,
// velocity, attitude and body rates and flies on from there (the instructor's "take control
// from here"). A replayed sample that is not finite is refused and counted.
#pragma once

#include "flight/model/aircraft/initial_conditions.hpp"
#include "fedsim/msg/aircraft_state.h"

#include <cstdint>
#include <optional>
#include <string>

namespace fedsim::flight {

class ReplayPlayback {
 public:
  /// Frames without a new replayed sample after which the replay is over.
  static constexpr int kHoldFrames = 10;

  enum class Event { kNone, kStarted, kEnded };

  /// Once per frame, with the replay port's update count and newest sample (nullptr: none yet).
  /// A sample that fails replay_sample_problem() is not taken (the caller counts the fault);
  /// `problem` says why.
  Event update(std::uint64_t updates, const msg::AircraftState* latest, std::string& problem);
  /// The replay drives the aircraft state this frame.
  bool active() const { return active_; }
  /// The newest replayed sample taken.
  const msg::AircraftState& last() const { return last_; }
  std::uint64_t samples() const { return samples_; }

 private:
  bool active_ = false;
  std::uint64_t seen_updates_ = 0;
  int frames_since_sample_ = 0;
  std::uint64_t samples_ = 0;
  msg::AircraftState last_;
};

/// "" if `s` can drive the aircraft: position, velocity, attitude and rates finite, latitude
/// within +-90 deg; else the first field that cannot.
std::string replay_sample_problem(const msg::AircraftState& s);

/// The model state that continues from a replayed sample (position, NED velocity, Euler
/// attitude, body rates w.r.t. inertial space, as the message carries them).
AircraftInitialConditions state_from_replay(const msg::AircraftState& s);

}  // namespace fedsim::flight
