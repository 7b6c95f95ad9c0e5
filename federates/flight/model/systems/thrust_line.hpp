// Where a thruster acts and which way it pushes, in the pack reference frame.
#pragma once

#include <Eigen/Core>
#include <string>

namespace fedsim::flight {

/// A thruster's point of action and direction.
///
/// position_m: body axes (x forward, y right, z down), metres from the pack datum.
/// pitch_rad:  thrust line tilted nose-up by this angle (positive: thrust has an upward,
///             i.e. -z, component).
/// yaw_rad:    thrust line turned to the right by this angle (positive: +y component).
struct ThrustLine {
  Eigen::Vector3d position_m = Eigen::Vector3d::Zero();
  double pitch_rad = 0.0;
  double yaw_rad = 0.0;

  /// Unit vector along the thrust, body axes: (cos p cos y, cos p sin y, -sin p).
  Eigen::Vector3d axis_body() const;
  /// Throws std::invalid_argument naming `prefix` + the bad field.
  void validate(const std::string& prefix) const;
};

}  // namespace fedsim::flight
