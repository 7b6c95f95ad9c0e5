// WGS-84 geodesy (geodetic <-> ECEF, local NED axes) and J2 gravitation/gravity (seed 3.5.6-3.5.7).
#pragma once

#include <Eigen/Core>

namespace fedsim {

/// Geodetic position on the WGS-84 ellipsoid.
struct GeodeticPosition {
  double lat_rad = 0.0;
  double lon_rad = 0.0;
  double alt_m = 0.0;  // height above the ellipsoid
};

/// WGS-84 defining and derived constants (NIMA TR8350.2, 3rd edition, tables 3.1-3.3).
namespace wgs84 {
inline constexpr double kSemiMajorAxisM = 6378137.0;
inline constexpr double kFlattening = 1.0 / 298.257223563;
inline constexpr double kSemiMinorAxisM = kSemiMajorAxisM * (1.0 - kFlattening);
inline constexpr double kEccentricitySquared = kFlattening * (2.0 - kFlattening);
inline constexpr double kGmM3ps2 = 3.986004418e14;     // earth's gravitational constant
inline constexpr double kEarthRateRadps = 7.292115e-5;   // rotation rate about the ECEF z axis
inline constexpr double kJ2 = 1.08262982131e-3;        // -sqrt(5) * C(2,0) of EGM96/WGS-84
}  // namespace wgs84

/// Static helpers on the WGS-84 ellipsoid. None allocates.
class Wgs84 {
 public:
  /// Geodetic to earth-centred earth-fixed position (GeographicLib::Geocentric, exact).
  static Eigen::Vector3d ecef_from_geodetic(const GeodeticPosition& position);
  /// ECEF to geodetic (GeographicLib::Geocentric, closed form, accurate to nanometres).
  static GeodeticPosition geodetic_from_ecef(const Eigen::Vector3d& position_ecef_m);

  /// Rotation taking ECEF components to local north-east-down components at a lat/lon:
  /// v_ned = ned_from_ecef(lat, lon) * v_ecef. Its transpose maps NED to ECEF.
  static Eigen::Matrix3d ned_from_ecef(double lat_rad, double lon_rad);

  /// Earth's angular velocity relative to inertial space, ECEF components (rad/s).
  static Eigen::Vector3d earth_rate_ecef();

  /// Gravitational attraction of the oblate earth including the J2 zonal term (m/s², ECEF).
  static Eigen::Vector3d gravitation_ecef(const Eigen::Vector3d& position_ecef_m);
  /// Gravity felt by a body at rest on the rotating earth: gravitation minus the centripetal
  /// acceleration omega x (omega x r) (m/s², ECEF).
  static Eigen::Vector3d gravity_ecef(const Eigen::Vector3d& position_ecef_m);

  /// Radii of curvature at a latitude: meridian (north-south) and prime vertical (east-west).
  static double meridian_radius_m(double lat_rad);
  static double prime_vertical_radius_m(double lat_rad);
};

}  // namespace fedsim
