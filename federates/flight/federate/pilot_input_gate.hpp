// The flight federate's gate on pilot controls from outside (issue 11 item 5), pure logic with
// no DDS: which samples of fedsim/pilot_controls the model may fly, and what is worth a warning.
//
// Each new sample is offered with the frame that reads it. It is flown (becomes the last good
// input) only if
//   - it is for this aircraft (aircraft_id; another aircraft's sample is ignored:
//     kOtherAircraft),
//   - every value is finite (kNotFinite: NaN, +-Inf) and inside its range (kOutOfRange:
//     primaries, trims and steering -1..1; levers, flaps and brakes 0..1 - 1e30 is not clamped,
//     it is refused), and
//   - its frame stamp is plausible (kBadStamp): not after the frame that reads it, and not more
//     than `max_stamp_age_frames` before it (a sample stamped 2^62, or one from a writer whose
//     frame count is not the federation's, is not flown).
// A refused sample never changes what is flown: the last good input stays (so in relative mode
// the trim the deltas fly about is kept, where a NaN once became 0). Until a first good sample,
// there is no input (the federate flies its start controls).
//
// Writers: one owner per aircraft (qos/fedsim_qos.xml, profile pilot_controls: exclusive
// ownership). When a second matched writer appears, writers_matched() says so once (until the
// count falls back to one), for a warning: the strongest writer flies, the others are ignored.
//
// Hold: each frame the federate says whether a new good sample was flown; after
// `hold_after_frames` frames without one (a silent writer, or one writing only refused samples)
// the input is held (the last good one flown, frames counted) and
// frame() says so once, and again once when samples come back. The federation is never
// waited for beyond the runtime's input timeout: a silent writer costs at most that, then the
// held input flies.
#pragma once

#include "fedsim/msg/controls.h"

#include <array>
#include <atomic>
#include <cstdint>
#include <optional>
#include <string>

namespace fedsim::flight {

enum class InputRejection { kOtherAircraft, kNotFinite, kOutOfRange, kBadStamp };
inline constexpr std::size_t kInputRejectionKinds = 4;

/// The fault kind a rejection is counted under, e.g. "controls_not_finite".
const char* fault_kind(InputRejection why);

struct PilotInputLimits {
  int aircraft_id = 0;                      // the aircraft these controls must be for
  std::uint64_t max_stamp_age_frames = 50;  // oldest plausible stamp, frames before the reader's
  std::uint64_t hold_after_frames = 10;     // frames without a sample before the input is "held"
};

/// Why a sample cannot be flown (kind and a message naming the field and value), or nullopt.
struct InputProblem {
  InputRejection kind;
  std::string message;
};
std::optional<InputProblem> check_pilot_input(const msg::PilotControls& sample, std::uint64_t frame,
                                              const PilotInputLimits& limits);

/// The first screen, where samples arrive (the port's Input::accept_only; over DDS on a
/// middleware thread, hence atomics): a sample for another aircraft, or one stamped more than
/// max_stamp_age_frames after the newest frame started, never reaches the port - so it can
/// neither hide this aircraft's sample of the same frame nor count as the frame's lockstep
/// input - and is counted here for the federate to report.
class PilotInputScreen {
 public:
  explicit PilotInputScreen(PilotInputLimits limits) : limits_(limits) {}
  bool accept(const msg::PilotControls& sample);
  /// The frame thread, at the start of each frame.
  void frame_started(std::uint64_t frame) { newest_frame_.store(static_cast<std::int64_t>(frame)); }
  std::uint64_t other_aircraft() const { return other_aircraft_.load(); }
  std::uint64_t future_stamps() const { return future_stamps_.load(); }
  int last_other_aircraft_id() const { return last_other_id_.load(); }
  std::uint64_t last_future_stamp() const { return last_future_stamp_.load(); }

 private:
  PilotInputLimits limits_;
  std::atomic<std::int64_t> newest_frame_{-1};  // none yet: any stamp passes (a late joiner)
  std::atomic<std::uint64_t> other_aircraft_{0};
  std::atomic<std::uint64_t> future_stamps_{0};
  std::atomic<int> last_other_id_{-1};
  std::atomic<std::uint64_t> last_future_stamp_{0};
};

class PilotInputGate {
 public:
  explicit PilotInputGate(PilotInputLimits limits = {});

  /// A new sample read in `frame`: nullopt if it is flown from now on, else why not (counted;
  /// the last good input stays).
  std::optional<InputProblem> offer(const msg::PilotControls& sample, std::uint64_t frame);

  enum class WriterEvent { kNone, kSecondWriter, kSingleWriterAgain };
  /// The number of matched writers now (-1: unknown, ignored).
  WriterEvent writers_matched(int count);

  enum class HoldEvent { kNone, kHoldStarted, kHoldEnded };
  /// Once per frame; `new_sample`: a sample was accepted this frame.
  HoldEvent frame(std::uint64_t frame, bool new_sample);

  /// The input flown now (nullptr until a first good sample).
  const msg::PilotControls* last_good() const { return have_good_ ? &last_good_ : nullptr; }
  std::uint64_t accepted() const { return accepted_; }
  std::uint64_t rejected(InputRejection why) const { return rejected_[static_cast<std::size_t>(why)]; }
  std::uint64_t rejected_total() const;
  /// Frames flown on a held input (beyond hold_after_frames without a sample), in all holds.
  std::uint64_t held_frames() const { return held_frames_; }
  /// Frames since the last new sample at the latest frame().
  std::uint64_t quiet_frames() const { return quiet_frames_; }
  bool holding() const { return holding_; }
  std::uint64_t second_writer_events() const { return second_writer_events_; }
  const PilotInputLimits& limits() const { return limits_; }

 private:
  PilotInputLimits limits_;
  msg::PilotControls last_good_;
  bool have_good_ = false;
  std::uint64_t accepted_ = 0;
  std::array<std::uint64_t, kInputRejectionKinds> rejected_{};
  bool several_writers_ = false;
  std::uint64_t second_writer_events_ = 0;
  std::uint64_t quiet_frames_ = 0;
  bool holding_ = false;
  std::uint64_t held_frames_ = 0;
};

}  // namespace fedsim::flight
