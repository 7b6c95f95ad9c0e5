// Position, velocity and attitude of a vehicle on the WGS-84 ellipsoid: what the INS computes
// and what the truth (the flight model) is, so the two compare field by field.
// Frames: geodetic latitude/longitude/height (WGS-84), NED velocity over the ground, attitude as
// q_ned_from_body (scalar first, v_ned = q v_body q*), docs/frames.md.
#pragma once

#include "common/geodesy/wgs84.hpp"
#include "common/math/rotation.hpp"
#include "common/units/units.hpp"

#include <Eigen/Core>
#include <Eigen/Geometry>

#include <string_view>

namespace fedsim::nav {

struct NavigationState {
  GeodeticPosition position;                                    // lat, lon [rad], height [m]
  Eigen::Vector3d velocity_ned_mps = Eigen::Vector3d::Zero();   // over the ground, NED [m/s]
  Eigen::Quaterniond q_ned_from_body = Eigen::Quaterniond::Identity();  // attitude [-]
};

/// Largest |latitude| the local-level NED mechanisation accepts: tan(L) in the transport rate
/// and sec(L) in the longitude rate are singular at the poles (use a wander-azimuth frame there,
/// Titterton & Weston section 3.5.4).
inline constexpr double kMaxNedLatitudeRad = 89.5 * units::kDegToRad;
/// Heights accepted: below the deepest terrain to beyond any aircraft [m].
inline constexpr double kMinHeightM = -1000.0;
inline constexpr double kMaxHeightM = 100000.0;
/// Largest speed over the ground accepted [m/s] (Mach ~10).
inline constexpr double kMaxSpeedMps = 3000.0;

/// Throws std::invalid_argument naming `origin` if the state is not finite or out of range
/// (|lat| <= kMaxNedLatitudeRad, |lon| <= 2 pi, height and speed limits, |q| within 1e-6 of 1
/// before normalising).
void check_navigation_state(const NavigationState& state, std::string_view origin);

/// Errors of an estimate against the truth, resolved in the truth's local NED frame.
struct NavigationErrors {
  Eigen::Vector3d position_ned_m = Eigen::Vector3d::Zero();   // estimate - truth [m]
  double horizontal_position_m = 0.0;                         // |north, east| [m]
  Eigen::Vector3d velocity_ned_mps = Eigen::Vector3d::Zero(); // estimate - truth [m/s]
  // Small rotation phi with C_estimate = (I + [phi x]) C_truth, NED components [rad].
  Eigen::Vector3d attitude_ned_rad = Eigen::Vector3d::Zero();
  EulerAngles euler_rad;                                      // estimate - truth, wrapped [rad]
};

/// The estimate's errors against the truth (position difference through ECEF, exact).
NavigationErrors navigation_errors(const NavigationState& estimate, const NavigationState& truth);

/// The truth state moved by initial errors: position offset (truth NED, metres), velocity
/// offset (NED), attitude tilt phi (NED rotation vector, C = exp([phi x]) C_truth).
NavigationState perturbed_state(const NavigationState& truth,
                                const Eigen::Vector3d& position_offset_ned_m,
                                const Eigen::Vector3d& velocity_offset_ned_mps,
                                const Eigen::Vector3d& tilt_ned_rad);

/// The quaternion of a rotation vector (exact: axis |v|, angle |v|).
Eigen::Quaterniond quaternion_from_rotation_vector(const Eigen::Vector3d& rotation_rad);
/// The rotation vector of a quaternion (angle in [0, pi]).
Eigen::Vector3d rotation_vector_from_quaternion(const Eigen::Quaterniond& q);

}  // namespace fedsim::nav
