// Steady wind: speed and meteorological "from" direction tabulated against altitude, as a
// north-east-down wind vector.
#include "flight/model/weather/wind_profile.hpp"
#include "common/units/units.hpp"

#include <cmath>
#include <numbers>
#include <stdexcept>
#include <string>

namespace fedsim::flight {

namespace {

[[noreturn]] void fail(const std::string& field, const std::string& rule) {
  throw std::invalid_argument("wind profile: " + field + " " + rule);
}

// Adds whole turns so that each direction is within half a turn of the previous one; linear
// interpolation of the result then turns the shorter way.
std::vector<double> unwrapped(std::vector<double> directions_rad) {
  for (std::size_t i = 1; i < directions_rad.size(); ++i) {
    const double step = directions_rad[i] - directions_rad[i - 1];
    directions_rad[i] -= units::kTwoPi * std::round(step / units::kTwoPi);
  }
  return directions_rad;
}
}  // namespace

void WindProfile::Params::validate() const {
  if (speed_mps.size() != altitude_m.size()) fail("speed_mps", "needs one entry per altitude");
  if (from_direction_rad.size() != altitude_m.size()) {
    fail("from_direction_rad", "needs one entry per altitude");
  }
  if (altitude_m.empty()) return;
  try {
    check_breakpoints(altitude_m, "altitude_m");
  } catch (const std::invalid_argument& e) {
    throw std::invalid_argument(std::string("wind profile: ") + e.what());
  }
  for (std::size_t i = 0; i < altitude_m.size(); ++i) {
    const std::string row = "[" + std::to_string(i) + "]";
    if (!(speed_mps[i] >= 0.0) || !std::isfinite(speed_mps[i])) {
      fail("speed_mps" + row, "must be finite and >= 0");
    }
    if (!std::isfinite(from_direction_rad[i])) fail("from_direction_rad" + row, "must be finite");
  }
}

WindProfile::WindProfile(Params params) : params_(std::move(params)) {
  params_.validate();
  if (params_.altitude_m.empty()) return;
  speed_ = Table1D(params_.altitude_m, params_.speed_mps);
  direction_ = Table1D(params_.altitude_m, unwrapped(params_.from_direction_rad));
}

Eigen::Vector3d WindProfile::ned_from(double speed_mps, double from_direction_rad) {
  return {-speed_mps * std::cos(from_direction_rad), -speed_mps * std::sin(from_direction_rad),
          0.0};
}

WindProfile::Outputs WindProfile::at(double altitude_m) const {
  Outputs out;
  if (speed_.empty()) return out;
  out.speed_mps = speed_(altitude_m);
  const double direction = direction_(altitude_m);
  out.from_direction_rad = direction - units::kTwoPi * std::floor(direction / units::kTwoPi);
  out.wind_ned_mps = ned_from(out.speed_mps, out.from_direction_rad);
  return out;
}

}  // namespace fedsim::flight
