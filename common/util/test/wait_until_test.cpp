#include "common/util/wait_until.hpp"

#include <gtest/gtest.h>

#include <chrono>

namespace fedsim::util {
namespace {

TEST(WaitUntil, ReturnsAsSoonAsTheConditionHolds) {
  int asked = 0;
  const auto start = std::chrono::steady_clock::now();
  EXPECT_TRUE(wait_until([&] { return ++asked == 3; }, 10.0, std::chrono::milliseconds(1)));
  EXPECT_EQ(asked, 3);
  EXPECT_LT(std::chrono::steady_clock::now() - start, std::chrono::seconds(5));
}

// The negative control: a condition that never holds is false, and only at the deadline.
TEST(WaitUntil, FalseAtTheDeadlineWhenTheConditionNeverHolds) {
  int asked = 0;
  const auto start = std::chrono::steady_clock::now();
  EXPECT_FALSE(wait_until([&] { return ++asked < 0; }, 0.05, std::chrono::milliseconds(5)));
  EXPECT_GE(std::chrono::steady_clock::now() - start, std::chrono::milliseconds(50));
  EXPECT_GE(asked, 2);
}

}  // namespace
}  // namespace fedsim::util
