// Where a thruster acts and which way it pushes, in the pack reference frame.
#include "flight/model/systems/thrust_line.hpp"

#include <cmath>
#include <numbers>

#include "flight/model/systems/param_checks.hpp"

namespace fedsim::flight {

Eigen::Vector3d ThrustLine::axis_body() const {
  return {std::cos(pitch_rad) * std::cos(yaw_rad), std::cos(pitch_rad) * std::sin(yaw_rad),
          -std::sin(pitch_rad)};
}

void ThrustLine::validate(const std::string& prefix) const {
  param_checks::finite(position_m, prefix + "position_m");
  param_checks::in_range(pitch_rad, -std::numbers::pi / 2, std::numbers::pi / 2,
                         prefix + "pitch_rad");
  param_checks::in_range(yaw_rad, -std::numbers::pi, std::numbers::pi, prefix + "yaw_rad");
}

}  // namespace fedsim::flight
