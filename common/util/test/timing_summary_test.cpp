// The benchmarks' one summary of frame times: median, nearest-rank p99, max, mean.
#include "common/util/timing_summary.hpp"

#include <gtest/gtest.h>

namespace fedsim::util {
namespace {

TEST(TimingSummary, MedianNearestRankP99MaxAndMean) {
  std::vector<double> ms;
  for (int i = 100; i >= 1; --i) ms.push_back(i);  // 1..100, unsorted
  const TimingSummary s = summarize_ms(ms);
  EXPECT_DOUBLE_EQ(s.median_ms, 51.0);
  EXPECT_DOUBLE_EQ(s.p99_ms, 99.0);  // 99 of 100 at or below
  EXPECT_DOUBLE_EQ(s.max_ms, 100.0);
  EXPECT_DOUBLE_EQ(s.mean_ms, 50.5);
  EXPECT_DOUBLE_EQ(summarize_ms({7.0}).p99_ms, 7.0);
  EXPECT_DOUBLE_EQ(summarize_ms({}).max_ms, 0.0);
}

}  // namespace
}  // namespace fedsim::util
