// Silence of a writer that should write every frame, counted in frames (pure logic, no DDS).
//
// It replaces a DDS deadline on the high-rate topics: a deadline re-arms a middleware timer on
// every write and every sample, which cost a third of a 9-federate lockstep's frame rate, and it
// counts wall-clock time, which means nothing in a lockstep run going as fast as it can or
// paused in a debugger. Frames mean the same in realtime and lockstep.
//
// Each frame the host calls observe(frame, matched, updated) for a read port: `matched` says a
// writer is matched to the reader, `updated` that a new sample arrived since the last frame.
// The watch answers kSilent once when a matched writer has written nothing for `limit_frames`
// frames (counted from the last sample, or from the match if it never wrote), kResumed once when
// a silent writer writes again, and kNone otherwise. A writer that unmatches (a lost federate,
// reported as such elsewhere) ends the episode without an event.
#pragma once

#include <cstdint>

namespace fedsim::timing {

class SilenceWatch {
 public:
  enum class Event { kNone, kSilent, kResumed };

  /// `limit_frames` = 0 turns the watch off.
  explicit SilenceWatch(std::uint64_t limit_frames) : limit_frames_(limit_frames) {}

  Event observe(std::uint64_t frame, bool matched, bool updated);

  bool silent() const { return silent_; }
  /// Frames since the last sample (or the match) at the latest observation.
  std::uint64_t quiet_frames() const { return quiet_frames_; }
  std::uint64_t limit_frames() const { return limit_frames_; }

 private:
  std::uint64_t limit_frames_;
  bool watching_ = false;        // a writer is matched
  std::uint64_t since_frame_ = 0;  // frame of the last sample, or of the match
  std::uint64_t quiet_frames_ = 0;
  bool silent_ = false;
};

}  // namespace fedsim::timing
