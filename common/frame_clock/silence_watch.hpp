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
// frames since its last sample, or for the first-sample limit since the match if it has not
// written yet; kResumed once when a silent writer writes again, and kNone otherwise.
//
// The first sample may take longer: discovery is two-sided, so a reader can match a joining
// writer well before that writer has matched the reader (or its federate the frame tick), and
// under packet loss the other side's discovery repairs take seconds (Fast DDS's built-in
// endpoints repair at their heartbeat period). The host sets the first-sample limit per frame
// (first_sample_frames_for): in lockstep the limit itself, each frame having waited for the input;
// in realtime the frames of kJoinGraceS, for frames then pass at the clock's rate whether or not
// the writer has joined (tests/hosts RealtimeLoss20: a controls writer matched 1.7 s before its
// first sample reached the flight federate, at 20 % loss). A writer that unmatches (a lost federate,
// reported as such elsewhere) ends the episode without an event.
#pragma once

#include <cstdint>

namespace fedsim::timing {

class SilenceWatch {
 public:
  enum class Event { kNone, kSilent, kResumed };

  /// Wall time a joining writer gets for its first sample in realtime [s].
  static constexpr double kJoinGraceS = 5.0;

  /// `limit_frames` = 0 turns the watch off; the first-sample limit starts equal to it.
  explicit SilenceWatch(std::uint64_t limit_frames)
      : limit_frames_(limit_frames), first_sample_frames_(limit_frames) {}

  /// The first-sample limit for a frame of `frame_period_s` in lockstep or realtime (above).
  static std::uint64_t first_sample_frames_for(std::uint64_t limit_frames, bool realtime, double frame_period_s);
  void set_first_sample_frames(std::uint64_t frames) { first_sample_frames_ = frames; }

  Event observe(std::uint64_t frame, bool matched, bool updated);

  bool silent() const { return silent_; }
  /// Frames since the last sample (or the match) at the latest observation.
  std::uint64_t quiet_frames() const { return quiet_frames_; }
  std::uint64_t limit_frames() const { return limit_frames_; }

 private:
  std::uint64_t limit_frames_;
  std::uint64_t first_sample_frames_;
  bool watching_ = false;        // a writer is matched
  bool written_ = false;         // it has written since it matched
  std::uint64_t since_frame_ = 0;  // frame of the last sample, or of the match
  std::uint64_t quiet_frames_ = 0;
  bool silent_ = false;
};

}  // namespace fedsim::timing
