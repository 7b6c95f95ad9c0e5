// Tests of the mapping between I/O channels and flight-model commands.
#include "flight/fly/control_mapping.hpp"

#include <gtest/gtest.h>

namespace fedsim::flight {
namespace {

using io::Channel;

TEST(ControlMapping, EveryChannelSurvivesTheRoundTrip) {
  AircraftControls c;
  c.elevator = 0.1;
  c.aileron = -0.2;
  c.rudder = 0.3;
  c.elevator_trim = -0.05;
  c.aileron_trim = 0.02;
  c.rudder_trim = -0.01;
  c.throttle = {0.1, 0.2, 0.3, 0.4};
  c.mixture = {0.9, 0.8, 0.7, 0.6};
  c.propeller = {0.5, 0.4, 0.3, 0.2};
  c.flaps = 0.5;
  c.speedbrake = 0.25;
  c.spoilers = 0.75;  // no I/O channel: comes back from the base
  c.gear_down = false;
  c.brake_left = 0.6;
  c.brake_right = 0.7;
  c.steering = -0.4;
  const io::ControlInputs channels = to_control_inputs(c);
  EXPECT_DOUBLE_EQ(channels[Channel::kThrottle3], 0.3);
  EXPECT_DOUBLE_EQ(channels[Channel::kGearDown], 0.0);
  EXPECT_DOUBLE_EQ(channels[Channel::kNosewheelSteering], -0.4);
  EXPECT_EQ(from_control_inputs(channels, c), c);
}

TEST(ControlMapping, AProfileDrivesOnlyItsChannels) {
  AircraftControls trimmed;
  trimmed.elevator = -0.2;
  trimmed.set_throttle(0.7);
  io::ControlInputs channels = to_control_inputs(trimmed);
  channels[Channel::kElevator] = 0.1;
  channels[Channel::kGearDown] = 0.4;  // below half: lever up
  const AircraftControls out = from_control_inputs(channels, trimmed);
  EXPECT_DOUBLE_EQ(out.elevator, 0.1);
  EXPECT_DOUBLE_EQ(out.throttle[0], 0.7);
  EXPECT_FALSE(out.gear_down);
}

}  // namespace
}  // namespace fedsim::flight
