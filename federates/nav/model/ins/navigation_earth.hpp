// The earth as the local-level (NED) strapdown mechanisation sees it: earth rate, transport
// rate, radii of curvature and gravity on the WGS-84 ellipsoid.
//
// Sources: Titterton & Weston, Strapdown Inertial Navigation Technology, 2nd ed. (2004),
// section 3.5.3 (local geographic frame mechanisation) and 3.7.2 (radii of curvature,
// eqs 3.83-3.84); cross-checked with Groves (2013) eqs 2.123 (earth rate in
// NED) and 5.44 (transport rate). Gravity: common/geodesy Wgs84::gravity_ecef (J2 gravitation
// minus the centripetal term, the plumb-line gravity g_l of T&W section 3.7.4) resolved in NED.
// All SI: rad, m, m/s, rad/s, m/s^2.
#pragma once

#include "common/geodesy/wgs84.hpp"

#include <Eigen/Core>

namespace fedsim::nav {

/// Radii of curvature at a latitude plus the height: R_N + h (meridian) and R_E + h (prime
/// vertical, the "transverse" radius) [m].
struct LocalRadii {
  double meridian_plus_height_m = 0.0;
  double transverse_plus_height_m = 0.0;
};
LocalRadii local_radii(double lat_rad, double height_m);

/// omega_ie^n = Omega [cos L, 0, -sin L]: the earth's rate w.r.t. inertial space, NED [rad/s].
Eigen::Vector3d earth_rate_ned(double lat_rad);

/// omega_en^n = [v_E / (R_E + h), -v_N / (R_N + h), -v_E tan L / (R_E + h)]: the rate of the
/// local-level frame w.r.t. the earth as it is carried over the curved surface, NED [rad/s].
Eigen::Vector3d transport_rate_ned(double lat_rad, double height_m,
                                   const Eigen::Vector3d& velocity_ned_mps);

/// Plumb-line gravity (gravitation + centrifugal) at a geodetic position, NED [m/s^2]
/// (about (0, 0, 9.8)).
Eigen::Vector3d gravity_ned(const GeodeticPosition& position);

}  // namespace fedsim::nav
