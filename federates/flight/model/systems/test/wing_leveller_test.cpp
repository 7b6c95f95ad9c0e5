// The wing leveller against its law: command = -(Kp phi + Ki integral(phi dt) + Kd dphi/dt),
// JSBSim's C172 gains (c172ap.xml: 50, 5, 17), its engagement, the ground and the stops.
#include "flight/model/systems/wing_leveller.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <stdexcept>

namespace fedsim::flight {
namespace {

constexpr double kDeg = 3.14159265358979323846 / 180.0;

WingLeveller::Params jsbsim_c172() {
  WingLeveller::Params p;
  p.bank_gain_per_rad = 50.0;
  p.bank_integral_gain_per_rad_s = 5.0;
  p.bank_rate_gain_per_radps = 17.0;
  return p;
}

WingLeveller::Inputs banked(double bank_rad, double rate_radps = 0.0) {
  WingLeveller::Inputs in;
  in.bank_rad = bank_rad;
  in.bank_rate_radps = rate_radps;
  in.engaged = true;
  return in;
}

TEST(WingLeveller, ProportionalAndRateTermsOpposeTheBank) {
  WingLeveller w(jsbsim_c172());
  w.step(0.0, banked(0.5 * kDeg));  // right wing down: left aileron
  EXPECT_NEAR(w.outputs().aileron_command, -50.0 * 0.5 * kDeg, 1e-12);
  w.step(0.0, banked(-0.5 * kDeg));
  EXPECT_NEAR(w.outputs().aileron_command, 50.0 * 0.5 * kDeg, 1e-12);
  w.step(0.0, banked(0.0, 0.01));  // rolling right at 0.01 rad/s
  EXPECT_NEAR(w.outputs().aileron_command, -17.0 * 0.01, 1e-12);
  EXPECT_TRUE(w.outputs().active);
}

TEST(WingLeveller, IntegralIsTheRectangularSumOfTheBank) {
  WingLeveller w(jsbsim_c172());
  const double bank = 0.2 * kDeg, dt = 0.02;
  for (int i = 1; i <= 50; ++i) {
    w.step(dt, banked(bank));
    EXPECT_NEAR(w.outputs().integral, 5.0 * bank * dt * i, 1e-12);
    EXPECT_NEAR(w.outputs().aileron_command, -(50.0 * bank + 5.0 * bank * dt * i), 1e-12);
  }
}

TEST(WingLeveller, IntegralStopsWhileTheSummedCommandIsSaturated) {
  WingLeveller w(jsbsim_c172());
  // 20 deg of bank: Kp phi = 17.5, far past the stop; the integral must not wind up...
  for (int i = 0; i < 100; ++i) w.step(0.02, banked(20.0 * kDeg));
  EXPECT_EQ(w.outputs().integral, 0.0);
  EXPECT_DOUBLE_EQ(w.outputs().aileron_command, -1.0);
  // ...but it does integrate where the sum is within the stops.
  w.step(0.02, banked(0.1 * kDeg));
  EXPECT_NEAR(w.outputs().integral, 5.0 * 0.1 * kDeg * 0.02, 1e-15);
}

TEST(WingLeveller, CommandLeavesRoomForThePilotsAileronWithinTheStops) {
  WingLeveller w(jsbsim_c172());
  WingLeveller::Inputs in = banked(-10.0 * kDeg);  // left wing down: right aileron
  in.pilot_aileron_command = 0.4;
  w.step(0.0, in);
  EXPECT_DOUBLE_EQ(w.outputs().aileron_command, 0.6);  // the sum reaches +1, no further
}

TEST(WingLeveller, DisengagedOrOnTheGroundItCommandsNothingAndForgetsItsIntegral) {
  WingLeveller w(jsbsim_c172());
  for (int i = 0; i < 10; ++i) w.step(0.02, banked(0.2 * kDeg));
  ASSERT_GT(w.outputs().integral, 0.0);
  WingLeveller::Inputs off = banked(0.2 * kDeg);
  off.engaged = false;
  w.step(0.02, off);
  EXPECT_EQ(w.outputs().aileron_command, 0.0);
  EXPECT_EQ(w.outputs().integral, 0.0);
  EXPECT_FALSE(w.outputs().active);

  WingLeveller::Inputs ground = banked(0.2 * kDeg);
  ground.weight_on_wheels = true;
  w.step(0.02, ground);
  EXPECT_EQ(w.outputs().aileron_command, 0.0);
  EXPECT_FALSE(w.outputs().active);
  // Negative control: a leveller not restricted to the air acts on the ground.
  WingLeveller::Params anywhere = jsbsim_c172();
  anywhere.airborne_only = false;
  WingLeveller a(anywhere);
  a.step(0.02, ground);
  EXPECT_LT(a.outputs().aileron_command, 0.0);
}

TEST(WingLeveller, ANonFiniteInputDisengagesItForTheStep) {
  WingLeveller w(jsbsim_c172());
  w.step(0.02, banked(std::numeric_limits<double>::quiet_NaN()));
  EXPECT_EQ(w.outputs().aileron_command, 0.0);
  EXPECT_FALSE(w.outputs().active);
  w.step(0.02, banked(0.1 * kDeg));
  EXPECT_TRUE(w.outputs().active);
  EXPECT_TRUE(std::isfinite(w.outputs().aileron_command));
}

TEST(WingLeveller, BankRateIsTheEulerRateOfEquation348) {
  // Wings level, pitch 0: the bank rate is p.
  EXPECT_DOUBLE_EQ(WingLeveller::bank_rate_radps(0.1, 0.2, 0.3, 0.0, 0.0), 0.1);
  // phi = 30 deg, theta = 10 deg: p + (q sin phi + r cos phi) tan theta.
  const double phi = 30.0 * kDeg, theta = 10.0 * kDeg;
  EXPECT_NEAR(WingLeveller::bank_rate_radps(0.1, 0.2, 0.3, phi, theta),
              0.1 + (0.2 * 0.5 + 0.3 * std::cos(phi)) * std::tan(theta), 1e-15);
  // At the vertical the Euler rates are undefined: p alone, finite.
  EXPECT_DOUBLE_EQ(WingLeveller::bank_rate_radps(0.1, 0.2, 0.3, phi, 90.0 * kDeg), 0.1);
}

TEST(WingLeveller, BadParametersAreNamed) {
  WingLeveller::Params p = jsbsim_c172();
  p.bank_gain_per_rad = std::numeric_limits<double>::quiet_NaN();
  try {
    WingLeveller{p};
    ADD_FAILURE() << "accepted a NaN gain";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("bank_gain_per_rad"), std::string::npos) << e.what();
  }
  p = jsbsim_c172();
  p.bank_rate_gain_per_radps = 1e6;
  EXPECT_THROW(WingLeveller{p}, std::invalid_argument);
  EXPECT_NO_THROW(WingLeveller{jsbsim_c172()});
}

}  // namespace
}  // namespace fedsim::flight
