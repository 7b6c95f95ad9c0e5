// Pilot commands: trims add to their primaries, everything is clamped and NaN-safe.
#include "flight/model/aircraft/aircraft_controls.hpp"

#include <gtest/gtest.h>

#include <cmath>

namespace fedsim::flight {
namespace {

TEST(AircraftControls, TrimAddsToThePrimaryAndTheSumIsClamped) {
  AircraftControls c;
  c.elevator = 0.3;
  c.elevator_trim = -0.1;
  EXPECT_DOUBLE_EQ(c.elevator_command(), 0.2);
  c.aileron = 0.8;
  c.aileron_trim = 0.5;
  EXPECT_DOUBLE_EQ(c.aileron_command(), 1.0);
  c.rudder = -0.8;
  c.rudder_trim = -0.5;
  EXPECT_DOUBLE_EQ(c.rudder_command(), -1.0);
}

TEST(AircraftControls, ClampedReplacesNaNByNeutralAndLimitsRanges) {
  AircraftControls c;
  c.elevator = NAN;
  c.throttle = {2.0, -1.0, NAN, 0.5};
  c.mixture[0] = NAN;
  c.flaps = 1.5;
  c.steering = -3.0;
  c.brake_left = NAN;
  const AircraftControls k = c.clamped();
  EXPECT_EQ(k.elevator, 0.0);
  EXPECT_EQ(k.throttle[0], 1.0);
  EXPECT_EQ(k.throttle[1], 0.0);
  EXPECT_EQ(k.throttle[2], 0.0);
  EXPECT_EQ(k.throttle[3], 0.5);
  EXPECT_EQ(k.mixture[0], 1.0);  // a lost mixture lever reads full rich, not cut-off
  EXPECT_EQ(k.flaps, 1.0);
  EXPECT_EQ(k.steering, -1.0);
  EXPECT_EQ(k.brake_left, 0.0);
  EXPECT_TRUE(std::isfinite(AircraftControls{c}.elevator_command()));
}

TEST(AircraftControls, DefaultsAreACockpitAtRest) {
  const AircraftControls c;
  EXPECT_EQ(c.throttle[0], 0.0);
  EXPECT_EQ(c.mixture[0], 1.0);
  EXPECT_EQ(c.propeller[3], 1.0);
  EXPECT_TRUE(c.gear_down);
  EXPECT_EQ(c, c.clamped());
}

}  // namespace
}  // namespace fedsim::flight
