#include "common/util/doorbell.hpp"

#include <gtest/gtest.h>

#include <chrono>
#include <thread>

namespace fedsim::util {
namespace {

using Clock = std::chrono::steady_clock;

TEST(Doorbell, WaitTimesOutWhenNobodyRings) {
  Doorbell bell;
  const auto start = Clock::now();
  bell.wait(bell.value(), std::chrono::milliseconds(30));
  EXPECT_GE(Clock::now() - start, std::chrono::milliseconds(25));
}

TEST(Doorbell, ARingBeforeTheWaitIsNotLost) {
  Doorbell bell;
  const std::uint32_t seen = bell.value();
  bell.ring();  // between the look and the wait
  const auto start = Clock::now();
  bell.wait(seen, std::chrono::seconds(5));
  EXPECT_LT(Clock::now() - start, std::chrono::seconds(1));
}

TEST(Doorbell, ARingFromAnotherThreadWakesTheWaiter) {
  Doorbell bell;
  for (int i = 0; i < 200; ++i) {
    const std::uint32_t seen = bell.value();
    std::thread ringer([&] { bell.ring(); });
    const auto start = Clock::now();
    bell.wait(seen, std::chrono::seconds(5));
    ringer.join();
    ASSERT_LT(Clock::now() - start, std::chrono::seconds(1)) << "round " << i;
    ASSERT_NE(bell.value(), seen);
  }
}

}  // namespace
}  // namespace fedsim::util
