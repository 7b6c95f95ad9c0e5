#include "common/util/latency_stats.hpp"

#include <gtest/gtest.h>

namespace fedsim::util {
namespace {

TEST(LatencyStats, PercentilesWithinOnePercent) {
  LatencyStats s;
  for (int i = 1; i <= 1000; ++i) s.add_ns(static_cast<std::uint64_t>(i) * 1000);  // 1..1000 us
  EXPECT_EQ(s.count(), 1000u);
  EXPECT_NEAR(s.percentile_us(50), 500.0, 6.0);
  EXPECT_NEAR(s.percentile_us(99), 990.0, 11.0);
  EXPECT_DOUBLE_EQ(s.max_us(), 1000.0);
  EXPECT_NEAR(s.mean_us(), 500.5, 1e-9);
}

TEST(LatencyStats, EmptyAndMerged) {
  LatencyStats a, b;
  EXPECT_EQ(a.percentile_us(99), 0.0);
  a.add_ns(1000);
  b.add_ns(3000);
  a.merge(b);
  EXPECT_EQ(a.count(), 2u);
  EXPECT_DOUBLE_EQ(a.max_us(), 3.0);
  EXPECT_DOUBLE_EQ(a.min_us(), 1.0);
}

}  // namespace
}  // namespace fedsim::util
