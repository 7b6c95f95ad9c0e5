// Realtime frame ticks as a safety cut-off sees them (the motion platform and the control
// loader, which must go safe on their own when the federation stops driving them). Pure logic,
// no DDS, no clock: the host's tick watchdog (runtime::Component::tick_watchdog_periods) says how
// long the ticks have been silent, the component says when a tick arrived.
//
// The rule (docs/soak.md, "tick watchdogs"): ONE late tick is ridden through, counted and logged;
// ticks that have STOPPED, or that come late again and again, cut off.
//   - silence up to `stop_periods` (2.5 frame periods: 50 ms at 50 Hz) is a late tick: the last
//     command is held (a platform's jack servos hold it on their own), and when the tick comes
//     it is counted as late, not a fault. A 1 h realtime soak on a shared VM saw one 32 ms gap
//     (1.6 periods) in 180,000 frames; cutting the motion off for that is a worse cue than
//     holding one frame.
//   - silence of `stop_periods` or more is a stop: cut off (0.02 s later than the old rule of
//     1.5 periods at 50 Hz; a stop is still caught within three frame periods).
//   - `burst_late_ticks` late ticks (3) within `burst_window_frames` frames (50: one second at
//     50 Hz) cut off too: a host that cannot keep the rate drives cues the pilot should not feel.
#pragma once

#include <cstdint>
#include <deque>

namespace fedsim::timing {

class TickGapWatch {
 public:
  struct Limits {
    double late_periods = 1.5;       // silence that makes a tick late [frame periods]
    double stop_periods = 2.5;       // silence that means the ticks stopped [frame periods]
    int burst_late_ticks = 3;        // this many late ticks ...
    std::uint64_t burst_window_frames = 50;  // ... within this many frames cut off
  };
  enum class Verdict { kOnTime, kLate, kStopped, kBurst };

  TickGapWatch() = default;
  explicit TickGapWatch(Limits limits) : limits_(limits) {}

  /// The host's watchdog: no tick for `silent_periods` frame periods (called again and again
  /// while the silence lasts). kLate: ride through (hold); kStopped: cut off now.
  Verdict on_silence(double silent_periods);
  /// A tick arrived and frame `frame` steps. kLate: it ended a late gap (counted); kBurst: and
  /// that late tick makes a burst (cut off); kOnTime otherwise (also after a stop: the cut-off
  /// was reported then).
  Verdict on_tick(std::uint64_t frame);

  std::uint64_t late_ticks() const { return late_ticks_; }
  /// The longest silence of the gap on_tick() just ended [frame periods].
  double last_gap_periods() const { return last_gap_periods_; }
  const Limits& limits() const { return limits_; }

 private:
  Limits limits_;
  double gap_periods_ = 0.0;   // the silence now (0: none seen)
  bool stopped_ = false;       // this silence was already a stop
  double last_gap_periods_ = 0.0;
  std::uint64_t late_ticks_ = 0;
  std::deque<std::uint64_t> recent_late_frames_;  // frames of the latest late ticks
};

}  // namespace fedsim::timing
