// Clamping of the pilot's normalised commands.
#include "flight/model/aircraft/aircraft_controls.hpp"

#include <algorithm>
#include <cmath>

namespace fedsim::flight {

namespace {
double clamp_or(double value, double lo, double hi, double if_nan) {
  return std::isnan(value) ? if_nan : std::clamp(value, lo, hi);
}
double sum_command(double primary, double trim) {
  return std::clamp(clamp_or(primary, -1.0, 1.0, 0.0) + clamp_or(trim, -1.0, 1.0, 0.0), -1.0, 1.0);
}
}  // namespace

double AircraftControls::elevator_command() const { return sum_command(elevator, elevator_trim); }
double AircraftControls::aileron_command() const { return sum_command(aileron, aileron_trim); }
double AircraftControls::rudder_command() const { return sum_command(rudder, rudder_trim); }

AircraftControls AircraftControls::clamped() const {
  AircraftControls c = *this;
  c.elevator = clamp_or(elevator, -1.0, 1.0, 0.0);
  c.aileron = clamp_or(aileron, -1.0, 1.0, 0.0);
  c.rudder = clamp_or(rudder, -1.0, 1.0, 0.0);
  c.elevator_trim = clamp_or(elevator_trim, -1.0, 1.0, 0.0);
  c.aileron_trim = clamp_or(aileron_trim, -1.0, 1.0, 0.0);
  c.rudder_trim = clamp_or(rudder_trim, -1.0, 1.0, 0.0);
  for (std::size_t i = 0; i < kMaxEngines; ++i) {
    c.throttle[i] = clamp_or(throttle[i], 0.0, 1.0, 0.0);
    c.mixture[i] = clamp_or(mixture[i], 0.0, 1.0, 1.0);
    c.propeller[i] = clamp_or(propeller[i], 0.0, 1.0, 1.0);
  }
  c.flaps = clamp_or(flaps, 0.0, 1.0, 0.0);
  c.speedbrake = clamp_or(speedbrake, 0.0, 1.0, 0.0);
  c.spoilers = clamp_or(spoilers, 0.0, 1.0, 0.0);
  c.brake_left = clamp_or(brake_left, 0.0, 1.0, 0.0);
  c.brake_right = clamp_or(brake_right, 0.0, 1.0, 0.0);
  c.steering = clamp_or(steering, -1.0, 1.0, 0.0);
  return c;
}

}  // namespace fedsim::flight
