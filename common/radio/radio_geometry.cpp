#include "common/radio/radio_geometry.hpp"

#include "common/geodesy/wgs84.hpp"
#include "common/units/units.hpp"

#include <Eigen/Core>
#include <GeographicLib/Geodesic.hpp>

#include <algorithm>
#include <cmath>

namespace fedsim::radio {

LinkGeometry link_geometry(const nav::GeoPoint& station, double lat_rad, double lon_rad,
                           double altitude_msl_m) {
  LinkGeometry link;
  double s12_m = 0.0;
  double azi1_deg = 0.0;
  double azi2_deg = 0.0;
  GeographicLib::Geodesic::WGS84().Inverse(
      station.lat_rad * units::kRadToDeg, station.lon_rad * units::kRadToDeg,
      lat_rad * units::kRadToDeg, lon_rad * units::kRadToDeg, s12_m, azi1_deg, azi2_deg);
  link.ground_distance_m = s12_m;
  link.azimuth_from_station_true_rad = wrap_two_pi(azi1_deg * units::kDegToRad);
  // azi2 is the forward azimuth at the aircraft (pointing away from the station).
  link.azimuth_to_station_true_rad = wrap_two_pi(azi2_deg * units::kDegToRad + units::kPi);

  const Eigen::Vector3d station_ecef =
      Wgs84::ecef_from_geodetic({station.lat_rad, station.lon_rad, station.elevation_m});
  const Eigen::Vector3d aircraft_ecef = Wgs84::ecef_from_geodetic({lat_rad, lon_rad, altitude_msl_m});
  const Eigen::Vector3d path_ned =
      Wgs84::ned_from_ecef(station.lat_rad, station.lon_rad) * (aircraft_ecef - station_ecef);
  link.slant_range_m = path_ned.norm();
  link.height_above_station_m = altitude_msl_m - station.elevation_m;
  link.elevation_angle_rad = std::atan2(-path_ned.z(), std::hypot(path_ned.x(), path_ned.y()));
  return link;
}

double ground_distance_m(const nav::GeoPoint& station, double lat_rad, double lon_rad) {
  double s12_m = 0.0;
  GeographicLib::Geodesic::WGS84().Inverse(station.lat_rad * units::kRadToDeg,
                                           station.lon_rad * units::kRadToDeg,
                                           lat_rad * units::kRadToDeg, lon_rad * units::kRadToDeg,
                                           s12_m);
  return s12_m;
}

double ground_distance_lower_bound_m(const nav::GeoPoint& station, double lat_rad, double lon_rad) {
  constexpr double kMinRadiusOfCurvatureM = wgs84::kSemiMajorAxisM * (1.0 - wgs84::kEccentricitySquared);
  const double dlat = lat_rad - station.lat_rad;
  const double dlon = lon_rad - station.lon_rad;
  const double h = std::sin(0.5 * dlat) * std::sin(0.5 * dlat) +
                   std::cos(lat_rad) * std::cos(station.lat_rad) * std::sin(0.5 * dlon) *
                       std::sin(0.5 * dlon);  // haversine
  return 0.995 * kMinRadiusOfCurvatureM * 2.0 * std::asin(std::sqrt(std::min(1.0, h)));
}

double effective_earth_radius_m() {
  const double mean_radius_m = (2.0 * wgs84::kSemiMajorAxisM + wgs84::kSemiMinorAxisM) / 3.0;
  return kEffectiveEarthFactor * mean_radius_m;
}

double radio_line_of_sight_m(double height1_msl_m, double height2_msl_m) {
  const double two_kr = 2.0 * effective_earth_radius_m();
  return std::sqrt(two_kr * std::max(0.0, height1_msl_m)) +
         std::sqrt(two_kr * std::max(0.0, height2_msl_m));
}

bool within_radio_line_of_sight(double station_msl_m, double aircraft_msl_m,
                                double ground_distance_m) {
  return ground_distance_m <= radio_line_of_sight_m(station_msl_m, aircraft_msl_m);
}

double wrap_two_pi(double angle_rad) {
  double wrapped = std::fmod(angle_rad, units::kTwoPi);
  if (wrapped < 0.0) wrapped += units::kTwoPi;
  return wrapped >= units::kTwoPi ? 0.0 : wrapped;
}

}  // namespace fedsim::radio
