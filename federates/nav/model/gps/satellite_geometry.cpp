// Look angles and the local ENU frame.
#include "federates/nav/model/gps/satellite_geometry.hpp"

#include "common/geodesy/wgs84.hpp"
#include "common/units/units.hpp"

#include <cmath>
#include <stdexcept>

namespace fedsim::nav {

Eigen::Matrix3d enu_from_ecef(const Eigen::Vector3d& receiver_ecef_m) {
  const GeodeticPosition p = Wgs84::geodetic_from_ecef(receiver_ecef_m);
  const Eigen::Matrix3d ned = Wgs84::ned_from_ecef(p.lat_rad, p.lon_rad);
  Eigen::Matrix3d enu;
  enu.row(0) = ned.row(1);
  enu.row(1) = ned.row(0);
  enu.row(2) = -ned.row(2);
  return enu;
}

LookAngles look_angles(const Eigen::Vector3d& receiver_ecef_m,
                       const Eigen::Vector3d& satellite_ecef_m) {
  if (!receiver_ecef_m.allFinite() || !satellite_ecef_m.allFinite()) {
    throw std::invalid_argument("look_angles: a position is not finite");
  }
  const Eigen::Vector3d delta = satellite_ecef_m - receiver_ecef_m;
  LookAngles out;
  out.range_m = delta.norm();
  if (out.range_m <= 0.0) throw std::invalid_argument("look_angles: the positions coincide");
  out.line_of_sight_ecef = delta / out.range_m;
  const Eigen::Vector3d enu = enu_from_ecef(receiver_ecef_m) * out.line_of_sight_ecef;
  out.elevation_rad = std::asin(std::clamp(enu.z(), -1.0, 1.0));
  out.azimuth_rad = std::atan2(enu.x(), enu.y());
  if (out.azimuth_rad < 0.0) out.azimuth_rad += units::kTwoPi;
  return out;
}

}  // namespace fedsim::nav
