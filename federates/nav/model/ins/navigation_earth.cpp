// Earth rate, transport rate, radii and gravity for the NED mechanisation.
#include "federates/nav/model/ins/navigation_earth.hpp"

#include <cmath>

namespace fedsim::nav {

LocalRadii local_radii(double lat_rad, double height_m) {
  // T&W eqs 3.83 (R_N, meridian) and 3.84 (R_E, prime vertical).
  return {Wgs84::meridian_radius_m(lat_rad) + height_m,
          Wgs84::prime_vertical_radius_m(lat_rad) + height_m};
}

Eigen::Vector3d earth_rate_ned(double lat_rad) {
  return wgs84::kEarthRateRadps * Eigen::Vector3d(std::cos(lat_rad), 0.0, -std::sin(lat_rad));
}

Eigen::Vector3d transport_rate_ned(double lat_rad, double height_m,
                                   const Eigen::Vector3d& velocity_ned_mps) {
  const LocalRadii r = local_radii(lat_rad, height_m);
  const double v_n = velocity_ned_mps.x();
  const double v_e = velocity_ned_mps.y();
  return {v_e / r.transverse_plus_height_m, -v_n / r.meridian_plus_height_m,
          -v_e * std::tan(lat_rad) / r.transverse_plus_height_m};
}

Eigen::Vector3d gravity_ned(const GeodeticPosition& position) {
  return Wgs84::ned_from_ecef(position.lat_rad, position.lon_rad) *
         Wgs84::gravity_ecef(Wgs84::ecef_from_geodetic(position));
}

}  // namespace fedsim::nav
