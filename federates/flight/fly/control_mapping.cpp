// Conversion between I/O channels and flight-model commands (one place for the mapping).
#include "flight/fly/control_mapping.hpp"

namespace fedsim::flight {

using io::Channel;

io::ControlInputs to_control_inputs(const AircraftControls& c) {
  io::ControlInputs in = io::default_controls();
  in[Channel::kElevator] = c.elevator;
  in[Channel::kAileron] = c.aileron;
  in[Channel::kRudder] = c.rudder;
  in[Channel::kElevatorTrim] = c.elevator_trim;
  in[Channel::kAileronTrim] = c.aileron_trim;
  in[Channel::kRudderTrim] = c.rudder_trim;
  for (int e = 0; e < io::kMaxEngines; ++e) {
    const auto i = static_cast<std::size_t>(e);
    in.value[static_cast<std::size_t>(Channel::kThrottle1) + i] = c.throttle[i];
    in.value[static_cast<std::size_t>(Channel::kMixture1) + i] = c.mixture[i];
    in.value[static_cast<std::size_t>(Channel::kPropeller1) + i] = c.propeller[i];
  }
  in[Channel::kFlaps] = c.flaps;
  in[Channel::kSpeedbrake] = c.speedbrake;
  in[Channel::kGearDown] = c.gear_down ? 1.0 : 0.0;
  in[Channel::kBrakeLeft] = c.brake_left;
  in[Channel::kBrakeRight] = c.brake_right;
  in[Channel::kNosewheelSteering] = c.steering;
  return in;
}

AircraftControls from_control_inputs(const io::ControlInputs& in, const AircraftControls& base) {
  static_assert(io::kMaxEngines == AircraftControls::kMaxEngines);
  AircraftControls c = base;
  c.elevator = in[Channel::kElevator];
  c.aileron = in[Channel::kAileron];
  c.rudder = in[Channel::kRudder];
  c.elevator_trim = in[Channel::kElevatorTrim];
  c.aileron_trim = in[Channel::kAileronTrim];
  c.rudder_trim = in[Channel::kRudderTrim];
  for (int e = 0; e < io::kMaxEngines; ++e) {
    const auto i = static_cast<std::size_t>(e);
    c.throttle[i] = in.throttle(e);
    c.mixture[i] = in.mixture(e);
    c.propeller[i] = in.propeller(e);
  }
  c.flaps = in[Channel::kFlaps];
  c.speedbrake = in[Channel::kSpeedbrake];
  c.gear_down = in[Channel::kGearDown] >= 0.5;
  c.brake_left = in[Channel::kBrakeLeft];
  c.brake_right = in[Channel::kBrakeRight];
  c.steering = in[Channel::kNosewheelSteering];
  return c;
}

}  // namespace fedsim::flight
