#include "visual/model/scene_frame.hpp"

#include "common/units/units.hpp"
#include "common/util/input_checks.hpp"

#include <cmath>

namespace fedsim::visual {

SceneFrame::SceneFrame(const GeodeticPosition& origin) : origin_(origin) {
  util::require_in_range(origin.lat_rad, -units::kHalfPi, units::kHalfPi, "SceneFrame origin", "lat_rad",
                   "rad");
  util::require_in_range(origin.lon_rad, -units::kPi, units::kPi, "SceneFrame origin", "lon_rad", "rad");
  util::require_in_range(origin.alt_m, -1000.0, 10000.0, "SceneFrame origin", "alt_m", "m");
  origin_ecef_m_ = Wgs84::ecef_from_geodetic(origin);
  scene_from_ecef_ = Wgs84::ned_from_ecef(origin.lat_rad, origin.lon_rad);
  ground_radius_m_ = std::sqrt(Wgs84::meridian_radius_m(origin.lat_rad) *
                               Wgs84::prime_vertical_radius_m(origin.lat_rad)) +
                     origin.alt_m;
}

Eigen::Vector3d SceneFrame::position_scene_m(const GeodeticPosition& point) const {
  return scene_from_ecef_ * (Wgs84::ecef_from_geodetic(point) - origin_ecef_m_);
}

GeodeticPosition SceneFrame::geodetic(const Eigen::Vector3d& position_scene_m) const {
  return Wgs84::geodetic_from_ecef(origin_ecef_m_ +
                                   scene_from_ecef_.transpose() * position_scene_m);
}

Eigen::Matrix3d SceneFrame::scene_from_local_ned(double lat_rad, double lon_rad) const {
  return scene_from_ecef_ * Wgs84::ned_from_ecef(lat_rad, lon_rad).transpose();
}

Eigen::Vector3d SceneFrame::up_scene(double lat_rad, double lon_rad) const {
  return -scene_from_local_ned(lat_rad, lon_rad).col(2);
}

}  // namespace fedsim::visual
