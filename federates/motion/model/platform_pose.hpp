// The pose of the motion platform and the six jack values, in the motion frames:
//   I (motion inertial): fixed to the floor, origin at the motion reference point (MRP, the
//     centroid of the upper joints) when the platform is at neutral; x forward, y right, z down.
//   P (platform): fixed to the upper platform (the cab), origin at the MRP; P = I at neutral.
// A pose is the position of P's origin in I and the 3-2-1 Euler angles (roll phi, pitch theta,
// yaw psi) that take I to P: v_i = dcm_from_euler(attitude) v_p (common/math/rotation.hpp).
#pragma once

#include <Eigen/Core>
#include <array>

#include "common/math/rotation.hpp"

namespace fedsim::motion {

inline constexpr int kJackCount = 6;

/// One value per jack (lengths [m], rates [m/s], ...), jack k as numbered in StewartGeometry.
using JackArray = std::array<double, kJackCount>;

struct PlatformPose {
  Eigen::Vector3d position_i_m = Eigen::Vector3d::Zero();  // surge, sway, heave (+ down) [m]
  EulerAngles attitude;  // roll, pitch, yaw of P relative to I [rad]
};

/// The pose as (x, y, z, phi, theta, psi) [m, m, m, rad, rad, rad].
using PoseVector = Eigen::Matrix<double, 6, 1>;
PoseVector to_vector(const PlatformPose& pose);
PlatformPose from_vector(const PoseVector& q);

/// The pose whose six components are those of `pose` times `scale` (towards neutral for
/// scale < 1): the workspace limiter's one-parameter family.
PlatformPose scaled(const PlatformPose& pose, double scale);

/// True when every component is finite.
bool is_finite(const PlatformPose& pose);

}  // namespace fedsim::motion
