#include "common/frame_clock/tick_gap_watch.hpp"

#include <algorithm>

namespace fedsim::timing {

namespace {
// The host calls the watchdog on a timer, never exactly at the limit: 2.4999999 periods of
// silence measured for a 50 ms gap is still 2.5.
constexpr double kTolerancePeriods = 1e-6;
}  // namespace

TickGapWatch::Verdict TickGapWatch::on_silence(double silent_periods) {
  if (!(silent_periods >= limits_.late_periods - kTolerancePeriods)) return Verdict::kOnTime;
  gap_periods_ = std::max(gap_periods_, silent_periods);
  if (stopped_ || silent_periods >= limits_.stop_periods - kTolerancePeriods) {
    stopped_ = true;
    return Verdict::kStopped;
  }
  return Verdict::kLate;
}

TickGapWatch::Verdict TickGapWatch::on_tick(std::uint64_t frame) {
  const bool late = gap_periods_ > 0.0 && !stopped_;
  last_gap_periods_ = gap_periods_;
  gap_periods_ = 0.0;
  stopped_ = false;
  if (!late) return Verdict::kOnTime;
  ++late_ticks_;
  recent_late_frames_.push_back(frame);
  while (!recent_late_frames_.empty() &&
         recent_late_frames_.front() + limits_.burst_window_frames <= frame) {
    recent_late_frames_.pop_front();
  }
  if (static_cast<int>(recent_late_frames_.size()) >= limits_.burst_late_ticks) {
    recent_late_frames_.clear();
    return Verdict::kBurst;
  }
  return Verdict::kLate;
}

}  // namespace fedsim::timing
