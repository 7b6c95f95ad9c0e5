#include "common/frame_clock/rate_slot.hpp"

#include <gtest/gtest.h>

#include <cmath>

namespace fedsim::timing {
namespace {

TEST(RateSlot, AtTheFrameRateEveryFrameIsANewSlot) {
  // The negative control: the plain product skips frames (this is what the tolerance fixes).
  int plain_skips = 0;
  for (std::uint64_t n = 1; n < 100000; ++n) {
    if (static_cast<std::int64_t>(std::floor(static_cast<double>(n) * 0.02 * 50.0)) !=
        static_cast<std::int64_t>(n))
      ++plain_skips;
    ASSERT_EQ(rate_slot(n, 0.02, 50.0), static_cast<std::int64_t>(n)) << n;
    ASSERT_EQ(rate_slot(n, 1.0 / 60.0, 60.0), static_cast<std::int64_t>(n)) << n;
  }
  EXPECT_GT(plain_skips, 100);
}

TEST(RateSlot, LowerRatesRunEveryKthFrame) {
  int runs = 0;
  std::int64_t last = -1;
  for (std::uint64_t n = 0; n < 5000; ++n) {
    const std::int64_t slot = rate_slot(n, 0.02, 10.0);  // 10 Hz at 50 Hz: every 5th frame
    if (slot != last) {
      EXPECT_EQ(n % 5, 0u) << n;
      ++runs;
      last = slot;
    }
  }
  EXPECT_EQ(runs, 1000);
  EXPECT_EQ(rate_slot(7, 0.02, 0.0), 0);  // off: one slot for ever
}

}  // namespace
}  // namespace fedsim::timing
