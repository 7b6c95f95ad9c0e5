// Receiver-to-satellite geometry (seed 6.11): line of sight, azimuth and elevation in the local
// east-north-up frame of the receiver's geodetic position, and visibility above a mask angle.
// Inputs: receiver and satellite positions, ECEF [m]. Outputs: angles [rad], range [m].
#pragma once

#include "common/units/units.hpp"

#include <Eigen/Core>

namespace fedsim::nav {

struct LookAngles {
  double azimuth_rad = 0.0;    // from true north, clockwise (east = pi/2), [0, 2 pi)
  double elevation_rad = 0.0;  // above the local horizontal (ellipsoid tangent plane)
  double range_m = 0.0;        // geometric range
  Eigen::Vector3d line_of_sight_ecef = Eigen::Vector3d::Zero();  // unit, receiver to satellite
};

/// Throws std::invalid_argument if either position is not finite or they coincide.
LookAngles look_angles(const Eigen::Vector3d& receiver_ecef_m,
                       const Eigen::Vector3d& satellite_ecef_m);

/// Rotation taking ECEF components to local east-north-up components at the receiver's
/// geodetic latitude and longitude (rows: east, north, up).
Eigen::Matrix3d enu_from_ecef(const Eigen::Vector3d& receiver_ecef_m);

/// Default mask angle: 5 deg, as the SPS Performance Standard's availability figures.
inline constexpr double kDefaultMaskAngleRad = 5.0 * units::kDegToRad;

}  // namespace fedsim::nav
