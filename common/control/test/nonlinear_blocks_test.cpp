// Rate limiter, position limiter, dead-band and gain.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "common/control/dead_band.hpp"
#include "common/control/gain.hpp"
#include "common/control/limiter.hpp"
#include "common/control/rate_limiter.hpp"

namespace fedsim::control {
namespace {

TEST(RateLimiter, RampsAtTheLimitedSlopeAndArrivesExactly) {
  const double dt = 0.01;
  RateLimiter limiter(2.0, 5.0, dt);  // rise 2/s, fall 5/s
  // 0 -> 10 at 2/s: 0.02 a step, there after 5 s (500 steps).
  for (int n = 1; n <= 500; ++n) {
    ASSERT_NEAR(limiter.step(10.0), 0.02 * n, 1e-9) << n;
  }
  EXPECT_EQ(limiter.step(10.0), 10.0);
  EXPECT_FALSE(limiter.limited());
  // 10 -> 0 at 5/s: 2 s (200 steps).
  for (int n = 1; n < 200; ++n) {
    ASSERT_NEAR(limiter.step(0.0), 10.0 - 0.05 * n, 1e-9) << n;
    ASSERT_TRUE(limiter.limited());
  }
  EXPECT_NEAR(limiter.step(0.0), 0.0, 1e-9);
}

TEST(RateLimiter, PassesChangesBelowTheLimitUnchanged) {
  RateLimiter limiter(1.0, 0.01);  // 0.01 a step both ways
  limiter.reset(3.0);
  for (int n = 0; n < 100; ++n) {
    const double u = 3.0 + 0.5 * std::sin(0.01 * n);  // slope at most 0.5/s
    ASSERT_EQ(limiter.step(u), u) << n;
  }
  // Negative control: a faster sine (slope 5/s) is limited.
  bool limited_once = false;
  for (int n = 0; n < 100; ++n) {
    limiter.step(3.0 + 0.5 * std::sin(0.1 * n));
    limited_once = limited_once || limiter.limited();
  }
  EXPECT_TRUE(limited_once);
}

TEST(Limiter, ClampsToItsLimits) {
  Limiter limiter(-0.5, 2.0);
  EXPECT_EQ(limiter.step(3.0), 2.0);
  EXPECT_TRUE(limiter.limited());
  EXPECT_EQ(limiter.step(-1.0), -0.5);
  EXPECT_EQ(limiter.step(1.25), 1.25);
  EXPECT_FALSE(limiter.limited());
  Limiter one_sided(0.0, std::numeric_limits<double>::infinity());
  EXPECT_EQ(one_sided.step(1e30), 1e30);
  EXPECT_EQ(one_sided.step(-3.0), 0.0);
}

TEST(DeadBand, IsZeroInsideAndContinuousAtTheEdges) {
  DeadBand band(1.0);
  EXPECT_EQ(band.step(0.0), 0.0);
  EXPECT_EQ(band.step(0.999), 0.0);
  EXPECT_EQ(band.step(-1.0), 0.0);
  EXPECT_DOUBLE_EQ(band.step(3.0), 2.0);
  EXPECT_DOUBLE_EQ(band.step(-3.5), -2.5);
  EXPECT_NEAR(band.step(1.0 + 1e-9), 1e-9, 1e-15);  // no jump just outside the edge
  DeadBand offset(-0.2, 0.6);
  EXPECT_EQ(offset.step(0.5), 0.0);
  EXPECT_DOUBLE_EQ(offset.step(1.0), 0.4);
  EXPECT_DOUBLE_EQ(offset.step(-1.0), -0.8);
  DeadBand none(0.0);
  EXPECT_EQ(none.step(0.25), 0.25);
}

TEST(Gain, ScalesAndMayBeScheduled) {
  Gain gain(-3.0);
  EXPECT_EQ(gain.step(2.0), -6.0);
  gain.set_gain(0.5);
  EXPECT_EQ(gain.step(2.0), 1.0);
  EXPECT_EQ(gain.output(), 1.0);
}

}  // namespace
}  // namespace fedsim::control
