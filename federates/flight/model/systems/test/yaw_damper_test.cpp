// The yaw damper: its gain schedule, the washout's exact step response, the authority limit
// and engagement.
#include "flight/model/systems/yaw_damper.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>

namespace fedsim::flight {
namespace {

YawDamper::Params jsbsim_737(double washout_s = 0.0) {
  YawDamper::Params p;
  p.gain_per_radps = Table1D({0.0, 0.1, 0.11}, {0.0, 0.0, -1.0});  // the JSBSim 737's schedule
  p.washout_time_constant_s = washout_s;
  return p;
}

TEST(YawDamper, OpposesTheYawRateAboveItsMachThreshold) {
  YawDamper d(jsbsim_737());
  d.step(0.02, {0.05, 0.4, true});
  EXPECT_DOUBLE_EQ(d.outputs().rudder_command, -0.05);  // nose right -> left rudder
  d.step(0.02, {0.05, 0.105, true});
  EXPECT_NEAR(d.outputs().rudder_command, -0.025, 1e-12);  // half way up the schedule
  d.step(0.02, {0.05, 0.05, true});
  EXPECT_EQ(d.outputs().rudder_command, 0.0);  // taxiing: off
  d.step(0.02, {0.05, 0.4, false});
  EXPECT_EQ(d.outputs().rudder_command, 0.0);  // disengaged
  d.step(0.02, {5.0, 0.4, true});
  EXPECT_EQ(d.outputs().rudder_command, -1.0);  // authority
}

TEST(YawDamper, WashoutStepResponseIsTheExponential) {
  // A step of yaw rate r0 at t = 0 through K tau s / (tau s + 1): K r0 exp(-t / tau), exactly at
  // every step (the low-pass state is integrated exactly).
  const double tau = 2.0, r0 = 0.1;
  YawDamper d(jsbsim_737(tau));
  d.reset(0.0, 0.5, true);
  double t = 0.0;
  for (const double dt : {0.01, 0.05, 0.3, 1.0, 0.02}) {
    d.step(dt, {r0, 0.5, true});
    t += dt;
    EXPECT_NEAR(d.outputs().rudder_command, -r0 * std::exp(-t / tau), 1e-12) << t;
  }
  // A steady turn needs no damper rudder once washed out; reset() starts there.
  d.reset(r0, 0.5, true);
  d.step(0.02, {r0, 0.5, true});
  EXPECT_NEAR(d.outputs().rudder_command, 0.0, 1e-15);
  // Without the washout the steady rate keeps its rudder (the JSBSim 737's pure gain).
  YawDamper pure(jsbsim_737());
  pure.reset(r0, 0.5, true);
  EXPECT_DOUBLE_EQ(pure.outputs().rudder_command, -r0);
}

TEST(YawDamper, BadParametersAreNamed) {
  YawDamper::Params p = jsbsim_737();
  p.authority = 0.0;
  EXPECT_THROW(YawDamper{p}, std::invalid_argument);
  p = jsbsim_737();
  p.washout_time_constant_s = -1.0;
  EXPECT_THROW(YawDamper{p}, std::invalid_argument);
  p = jsbsim_737();
  p.gain_per_radps = Table1D();
  EXPECT_THROW(YawDamper{p}, std::invalid_argument);
}

}  // namespace
}  // namespace fedsim::flight
