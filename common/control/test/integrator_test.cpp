// The limited integrator: the trapezoidal ramp, anti-windup by state clamping (with the windup
// of an unlimited integrator followed by a saturation as the negative control), reset.
#include "common/control/integrator.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>

#include "common/control/limiter.hpp"

namespace fedsim::control {
namespace {

TEST(Integrator, IntegratesAConstantInputAlongTheTrapezoidalRamp) {
  const double k = 1.5, dt = 0.01, u = 2.0;
  Integrator integrator(k, dt);
  for (int n = 0; n < 1000; ++n) {
    // From rest (u_{-1} = 0) the first trapezoid is half a step: y_n = K u dt (n + 1/2).
    ASSERT_NEAR(integrator.step(u), k * u * dt * (n + 0.5), 1e-12) << "n = " << n;
  }
}

TEST(Integrator, LeavesTheLimitAtOnceWhenTheInputReverses) {
  const double dt = 0.01;
  Integrator integrator(1.0, dt, -1.0, 1.0);
  for (int n = 0; n < 500; ++n) integrator.step(1.0);  // 5 s against a limit reached at 1 s
  EXPECT_EQ(integrator.output(), 1.0);
  EXPECT_TRUE(integrator.limited());
  // Released: the first step already leaves the limit by K u dt/2 ...
  EXPECT_NEAR(integrator.step(-1.0), 1.0 - 0.5 * dt, 1e-12);
  EXPECT_FALSE(integrator.limited());
  // ... and the output crosses zero after 1 s of -1, not 5 s.
  for (int n = 1; n < 100; ++n) integrator.step(-1.0);
  EXPECT_NEAR(integrator.output(), 0.0 + 0.5 * dt, 1e-12);
  for (int n = 0; n < 200; ++n) integrator.step(-1.0);
  EXPECT_EQ(integrator.output(), -1.0);
}

TEST(Integrator, WithoutTheStateLimitASaturatedOutputWindsUp) {
  // Negative control: the same integrator unlimited, saturated afterwards. Its state climbs to
  // 5 and the saturated output stays at the limit for 4 s after the input reverses.
  const double dt = 0.01;
  Integrator integrator(1.0, dt);
  Limiter saturation(-1.0, 1.0);
  for (int n = 0; n < 500; ++n) saturation.step(integrator.step(1.0));
  EXPECT_NEAR(integrator.output(), 5.0, 0.01);
  for (int n = 0; n < 390; ++n) {
    ASSERT_EQ(saturation.step(integrator.step(-1.0)), 1.0) << "n = " << n;
  }
}

TEST(Integrator, ResetSetsTheOutputAndTheTrapezoidMemory) {
  const double dt = 0.01;
  Integrator integrator(2.0, dt, -10.0, 10.0);
  integrator.reset(3.0);
  EXPECT_EQ(integrator.output(), 3.0);
  EXPECT_NEAR(integrator.step(1.0), 3.0 + 2.0 * 0.5 * dt, 1e-12);  // from rest: half a step
  integrator.reset(3.0, 1.0);
  EXPECT_NEAR(integrator.step(1.0), 3.0 + 2.0 * dt, 1e-12);  // continuing: a full step
  EXPECT_THROW(integrator.reset(11.0), std::invalid_argument);
  EXPECT_THROW(integrator.reset(std::nan("")), std::invalid_argument);
}

TEST(Integrator, PeekDoesNotMoveAndHoldForgetsTheLastInput) {
  Integrator integrator(1.0, 0.1);
  integrator.step(1.0);
  const double before = integrator.output();
  EXPECT_NEAR(integrator.peek(1.0), before + 0.1, 1e-12);
  EXPECT_EQ(integrator.output(), before);
  integrator.hold();
  EXPECT_EQ(integrator.output(), before);
  EXPECT_NEAR(integrator.step(1.0), before + 0.05, 1e-12);  // the trapezoid restarts
}

}  // namespace
}  // namespace fedsim::control
