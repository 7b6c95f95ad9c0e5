// Tests of the control-surface actuator: command mapping, lag, rate limit and stops.
#include "flight/model/systems/actuator.hpp"
#include "common/units/units.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <stdexcept>
#include <string>

namespace fedsim::flight {
namespace {

constexpr double kDeg = units::kDegToRad;

// JSBSim c172x elevator: command -1..1 maps to -28..+23 deg, lag 60 rad/s, clip +-0.34 rad.
Actuator::Params c172_elevator() {
  Actuator::Params p;
  p.deflection_at_plus_one_rad = 23.0 * kDeg;
  p.deflection_at_minus_one_rad = -28.0 * kDeg;
  p.time_constant_s = 1.0 / 60.0;
  p.position_min_rad = -0.34;
  p.position_max_rad = 0.34;
  return p;
}

TEST(Actuator, MapsCommandsWithSeparateTravelEachWay) {
  const Actuator a(c172_elevator());
  EXPECT_DOUBLE_EQ(a.demand_for(1.0), 23.0 * kDeg);
  EXPECT_DOUBLE_EQ(a.demand_for(-1.0), -28.0 * kDeg);
  EXPECT_DOUBLE_EQ(a.demand_for(0.5), 11.5 * kDeg);
  EXPECT_DOUBLE_EQ(a.demand_for(-0.25), -7.0 * kDeg);
  EXPECT_DOUBLE_EQ(a.demand_for(0.0), 0.0);
  EXPECT_DOUBLE_EQ(a.demand_for(3.0), 23.0 * kDeg);  // clamped command
  EXPECT_DOUBLE_EQ(a.demand_for(std::nan("")), 0.0);
}

TEST(Actuator, StepResponseFollowsTheFirstOrderLag) {
  Actuator::Params p;
  p.deflection_at_plus_one_rad = 0.3;
  p.deflection_at_minus_one_rad = -0.3;
  p.time_constant_s = 0.1;
  for (double dt : {0.0025, 0.02, 0.05}) {
    Actuator a(p);
    const int steps = static_cast<int>(std::lround(p.time_constant_s / dt));
    for (int i = 0; i < steps; ++i) a.step(dt, {1.0});
    // After one time constant: 1 - e^-1 = 63.2 % of the step, whatever the step size.
    EXPECT_NEAR(a.outputs().position_rad, 0.3 * (1.0 - std::exp(-1.0)), 1e-12) << "dt " << dt;
    for (int i = 0; i < 4 * steps; ++i) a.step(dt, {1.0});
    EXPECT_NEAR(a.outputs().position_rad, 0.3 * (1.0 - std::exp(-5.0)), 1e-12);
  }
}

TEST(Actuator, LagIsStableWithAStepLongerThanTheTimeConstant) {
  Actuator a(c172_elevator());  // tau = 16.7 ms
  for (int i = 0; i < 10; ++i) {
    a.step(0.05, {0.5});
    EXPECT_LE(a.outputs().position_rad, 11.5 * kDeg + 1e-15);  // no overshoot
  }
  EXPECT_NEAR(a.outputs().position_rad, 11.5 * kDeg, 1e-9);
}

TEST(Actuator, RateLimitGivesAConstantSlope) {
  // JSBSim c172x aileron: rate limit 1.57 rad/s, stops -0.35 / +0.26 rad, no lag.
  Actuator::Params p;
  p.deflection_at_plus_one_rad = 15.0 * kDeg;
  p.deflection_at_minus_one_rad = -20.0 * kDeg;
  p.rate_limit_radps = 1.57;
  p.position_min_rad = -0.35;
  p.position_max_rad = 0.26;
  Actuator a(p);
  const double dt = 1.0 / 400.0;
  const double target = 15.0 * kDeg;  // 0.2618 rad: beyond the +0.26 stop
  double t = 0.0;
  while (a.outputs().position_rad < 0.26 - 1e-12 && t < 1.0) {
    a.step(dt, {1.0});
    t += dt;
    if (a.outputs().position_rad < 0.26 - 1.57 * dt) {
      EXPECT_NEAR(a.outputs().rate_radps, 1.57, 1e-9);
      EXPECT_NEAR(a.outputs().position_rad, 1.57 * t, 1e-9);
    }
  }
  EXPECT_NEAR(t, 0.26 / 1.57, dt);
  a.step(dt, {1.0});
  EXPECT_DOUBLE_EQ(a.outputs().position_rad, 0.26);  // held at the stop, short of the demand
  EXPECT_GT(target, 0.26);
  // Reversal is rate limited too: full left (-20 deg) takes (0.26 + 0.349) / 1.57 s.
  const double full_left = -20.0 * kDeg;
  int steps = 0;
  while (a.outputs().position_rad > full_left + 1e-12 && steps < 10000) {
    a.step(dt, {-1.0});
    ++steps;
  }
  EXPECT_NEAR(steps * dt, (0.26 - full_left) / 1.57, dt);
}

TEST(Actuator, PositionLimitsSaturateTheSurface) {
  Actuator a(c172_elevator());
  for (int i = 0; i < 400; ++i) a.step(0.0025, {-1.0});  // demand -28 deg = -0.489 rad
  EXPECT_DOUBLE_EQ(a.outputs().position_rad, -0.34);
  EXPECT_NEAR(a.outputs().demand_rad, -28.0 * kDeg, 1e-15);
  for (int i = 0; i < 400; ++i) a.step(0.0025, {1.0});  // demand +23 deg = 0.401 rad
  EXPECT_DOUBLE_EQ(a.outputs().position_rad, 0.34);
}

TEST(Actuator, OneSidedCommandsIgnoreNegativeInput) {
  Actuator::Params flaps;
  flaps.command_min = 0.0;
  flaps.deflection_at_plus_one_rad = 30.0 * kDeg;
  flaps.rate_limit_radps = 5.0 * kDeg;  // 6 s full travel
  Actuator a(flaps);
  a.step(0.1, {-0.5});
  EXPECT_DOUBLE_EQ(a.outputs().position_rad, 0.0);
  for (int i = 0; i < 30; ++i) a.step(0.1, {1.0});
  EXPECT_NEAR(a.outputs().position_rad, 15.0 * kDeg, 1e-12);  // half way after 3 s
}

TEST(Actuator, ResetPlacesTheSurfaceWithinItsStops) {
  Actuator a(c172_elevator());
  a.reset(1.0);
  EXPECT_DOUBLE_EQ(a.outputs().position_rad, 0.34);
  EXPECT_DOUBLE_EQ(a.outputs().rate_radps, 0.0);
  a.reset();
  EXPECT_DOUBLE_EQ(a.outputs().position_rad, 0.0);
}

TEST(Actuator, ValidateNamesTheBadField) {
  auto expect_field = [](Actuator::Params p, const std::string& field) {
    try {
      p.validate();
      ADD_FAILURE() << "no exception for " << field;
    } catch (const std::invalid_argument& e) {
      EXPECT_NE(std::string(e.what()).find(field), std::string::npos) << e.what();
    }
  };
  Actuator::Params p = c172_elevator();
  p.time_constant_s = -1.0;
  expect_field(p, "time_constant_s");
  p = c172_elevator();
  p.rate_limit_radps = 0.0;
  expect_field(p, "rate_limit_radps");
  p = c172_elevator();
  p.position_max_rad = -0.5;
  expect_field(p, "position_max_rad");
  p = c172_elevator();
  p.deflection_at_plus_one_rad = std::nan("");
  expect_field(p, "deflection_at_plus_one_rad");
  p = c172_elevator();
  p.command_min = 0.5;
  expect_field(p, "command_min");
}

}  // namespace
}  // namespace fedsim::flight
