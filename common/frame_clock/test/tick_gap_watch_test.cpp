// The tick watchdog's rule for safety cut-offs (tick_gap_watch.hpp): one late tick is ridden
// through and counted; a stop or a burst of late ticks cuts off.
#include "common/frame_clock/tick_gap_watch.hpp"

#include <gtest/gtest.h>

namespace fedsim::timing {
namespace {

constexpr double kPeriodS = 0.02;  // 50 Hz
double periods(double seconds) { return seconds / kPeriodS; }

// The 1 h soak's case: one 32 ms gap (1.6 periods) between two ticks.
TEST(TickGapWatch, OneLateTickIsRiddenThroughAndCounted) {
  TickGapWatch watch;
  EXPECT_EQ(watch.on_tick(100), TickGapWatch::Verdict::kOnTime);
  EXPECT_EQ(watch.on_silence(periods(0.030)), TickGapWatch::Verdict::kLate);  // the host's call
  EXPECT_EQ(watch.on_tick(101), TickGapWatch::Verdict::kLate);                // at 32 ms
  EXPECT_EQ(watch.late_ticks(), 1u);
  EXPECT_DOUBLE_EQ(watch.last_gap_periods(), 1.5);
  EXPECT_EQ(watch.on_tick(102), TickGapWatch::Verdict::kOnTime);  // the next one on time
  EXPECT_EQ(watch.late_ticks(), 1u);
}

TEST(TickGapWatch, TicksThatStopCutOffAtTwoAndAHalfPeriods) {
  TickGapWatch watch;
  watch.on_tick(7);
  EXPECT_EQ(watch.on_silence(periods(0.030)), TickGapWatch::Verdict::kLate);
  EXPECT_EQ(watch.on_silence(periods(0.045)), TickGapWatch::Verdict::kLate);
  EXPECT_EQ(watch.on_silence(periods(0.050)), TickGapWatch::Verdict::kStopped);
  EXPECT_EQ(watch.on_silence(periods(0.070)), TickGapWatch::Verdict::kStopped);
  // When the ticks come back the stop was the fault; it is not also a late tick.
  EXPECT_EQ(watch.on_tick(8), TickGapWatch::Verdict::kOnTime);
  EXPECT_EQ(watch.late_ticks(), 0u);
}

TEST(TickGapWatch, ABurstOfLateTicksCutsOff) {
  TickGapWatch watch;
  watch.on_silence(periods(0.032));
  EXPECT_EQ(watch.on_tick(10), TickGapWatch::Verdict::kLate);
  watch.on_silence(periods(0.032));
  EXPECT_EQ(watch.on_tick(30), TickGapWatch::Verdict::kLate);
  watch.on_silence(periods(0.032));
  EXPECT_EQ(watch.on_tick(59), TickGapWatch::Verdict::kBurst);  // 3 within 50 frames
  EXPECT_EQ(watch.late_ticks(), 3u);
}

// Negative control for the burst: the same three late ticks spread over more than the window.
TEST(TickGapWatch, LateTicksFarApartAreEachRiddenThrough) {
  TickGapWatch watch;
  for (std::uint64_t frame : {10u, 60u, 110u, 160u}) {
    watch.on_silence(periods(0.032));
    EXPECT_EQ(watch.on_tick(frame), TickGapWatch::Verdict::kLate) << frame;
  }
  EXPECT_EQ(watch.late_ticks(), 4u);
}

TEST(TickGapWatch, SilenceShorterThanLateIsNothing) {
  TickGapWatch watch;
  EXPECT_EQ(watch.on_silence(periods(0.025)), TickGapWatch::Verdict::kOnTime);
  EXPECT_EQ(watch.on_tick(1), TickGapWatch::Verdict::kOnTime);
  EXPECT_EQ(watch.late_ticks(), 0u);
}

}  // namespace
}  // namespace fedsim::timing
