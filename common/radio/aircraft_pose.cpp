#include "common/radio/aircraft_pose.hpp"

#include "common/units/units.hpp"

#include <cmath>

namespace fedsim::radio {

namespace {
bool within(double value, double low, double high) {
  return std::isfinite(value) && value >= low && value <= high;
}
}  // namespace

std::string_view pose_problem(const AircraftPose& pose) {
  using units::kHalfPi;
  using units::kPi;
  using units::kTwoPi;
  if (!within(pose.lat_rad, -kHalfPi, kHalfPi)) return "lat_rad";
  if (!within(pose.lon_rad, -kTwoPi, kTwoPi)) return "lon_rad";
  if (!within(pose.altitude_msl_m, -1000.0, 100000.0)) return "altitude_msl_m";
  if (!std::isfinite(pose.heading_true_rad)) return "heading_true_rad";
  if (!within(pose.pitch_rad, -kHalfPi, kHalfPi)) return "pitch_rad";
  if (!within(pose.roll_rad, -kPi, kPi)) return "roll_rad";
  if (!within(pose.true_airspeed_mps, 0.0, 1000.0)) return "true_airspeed_mps";
  if (!within(pose.climb_rate_mps, -500.0, 500.0)) return "climb_rate_mps";
  return {};
}

}  // namespace fedsim::radio
