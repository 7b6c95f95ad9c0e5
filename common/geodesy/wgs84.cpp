// WGS-84 geodesy and J2 gravity.
#include "common/geodesy/wgs84.hpp"

#include <Eigen/Geometry>
#include <GeographicLib/Geocentric.hpp>

#include <cmath>

namespace fedsim {

namespace {
constexpr double kDegPerRad = 57.29577951308232;
}  // namespace

Eigen::Vector3d Wgs84::ecef_from_geodetic(const GeodeticPosition& position) {
  Eigen::Vector3d ecef;
  GeographicLib::Geocentric::WGS84().Forward(position.lat_rad * kDegPerRad,
                                             position.lon_rad * kDegPerRad, position.alt_m,
                                             ecef.x(), ecef.y(), ecef.z());
  return ecef;
}

GeodeticPosition Wgs84::geodetic_from_ecef(const Eigen::Vector3d& position_ecef_m) {
  double lat_deg = 0.0;
  double lon_deg = 0.0;
  GeodeticPosition geodetic;
  GeographicLib::Geocentric::WGS84().Reverse(position_ecef_m.x(), position_ecef_m.y(),
                                             position_ecef_m.z(), lat_deg, lon_deg,
                                             geodetic.alt_m);
  geodetic.lat_rad = lat_deg / kDegPerRad;
  geodetic.lon_rad = lon_deg / kDegPerRad;
  return geodetic;
}

Eigen::Matrix3d Wgs84::ned_from_ecef(double lat_rad, double lon_rad) {
  const double slat = std::sin(lat_rad);
  const double clat = std::cos(lat_rad);
  const double slon = std::sin(lon_rad);
  const double clon = std::cos(lon_rad);
  Eigen::Matrix3d c;
  c << -slat * clon, -slat * slon, clat,  //
      -slon, clon, 0.0,                   //
      -clat * clon, -clat * slon, -slat;
  return c;
}

Eigen::Vector3d Wgs84::earth_rate_ecef() { return {0.0, 0.0, wgs84::kEarthRateRadps}; }

Eigen::Vector3d Wgs84::gravitation_ecef(const Eigen::Vector3d& position_ecef_m) {
  // Gradient of U = -GM/r [1 - J2 (a/r)^2 (3 sin^2(lat_c) - 1) / 2] (e.g. Vallado, eq. 8-25).
  const double r2 = position_ecef_m.squaredNorm();
  const double r = std::sqrt(r2);
  const double z2_over_r2 = position_ecef_m.z() * position_ecef_m.z() / r2;
  const double j2_term =
      1.5 * wgs84::kJ2 * wgs84::kSemiMajorAxisM * wgs84::kSemiMajorAxisM / r2;
  const double scale = -wgs84::kGmM3ps2 / (r2 * r);
  return {scale * position_ecef_m.x() * (1.0 + j2_term * (1.0 - 5.0 * z2_over_r2)),
          scale * position_ecef_m.y() * (1.0 + j2_term * (1.0 - 5.0 * z2_over_r2)),
          scale * position_ecef_m.z() * (1.0 + j2_term * (3.0 - 5.0 * z2_over_r2))};
}

Eigen::Vector3d Wgs84::gravity_ecef(const Eigen::Vector3d& position_ecef_m) {
  const Eigen::Vector3d omega = earth_rate_ecef();
  return gravitation_ecef(position_ecef_m) - omega.cross(omega.cross(position_ecef_m));
}

double Wgs84::meridian_radius_m(double lat_rad) {
  const double s = std::sin(lat_rad);
  const double w2 = 1.0 - wgs84::kEccentricitySquared * s * s;
  return wgs84::kSemiMajorAxisM * (1.0 - wgs84::kEccentricitySquared) / (w2 * std::sqrt(w2));
}

double Wgs84::prime_vertical_radius_m(double lat_rad) {
  const double s = std::sin(lat_rad);
  return wgs84::kSemiMajorAxisM / std::sqrt(1.0 - wgs84::kEccentricitySquared * s * s);
}

}  // namespace fedsim
