#include "visual/model/runway_frame.hpp"

#include "common/units/units.hpp"

#include <GeographicLib/Geodesic.hpp>
#include <GeographicLib/GeodesicLine.hpp>

#include <algorithm>

namespace fedsim::visual {

using units::kDegToRad;
using units::kRadToDeg;

double RunwayProfile::elevation_m(double along_m) const {
  if (end_along_m == start_along_m) return start_elevation_m;
  const double t = std::clamp((along_m - start_along_m) / (end_along_m - start_along_m), 0.0, 1.0);
  return start_elevation_m + t * (end_elevation_m - start_elevation_m);
}

RunwayFrame::RunwayFrame(const SceneFrame& scene, double threshold_lat_rad,
                         double threshold_lon_rad, double heading_true_rad,
                         const RunwayProfile& profile)
    : scene_(&scene),
      lat_rad_(threshold_lat_rad),
      lon_rad_(threshold_lon_rad),
      heading_true_rad_(heading_true_rad),
      profile_(profile) {}

GeodeticPosition RunwayFrame::geodetic(double along_m, double right_m, double up_m) const {
  const auto& earth = GeographicLib::Geodesic::WGS84();
  double lat_deg = 0.0, lon_deg = 0.0, azimuth_deg = 0.0;
  earth.Direct(lat_rad_ * kRadToDeg, lon_rad_ * kRadToDeg, heading_true_rad_ * kRadToDeg, along_m,
               lat_deg, lon_deg, azimuth_deg);
  double lat2_deg = lat_deg, lon2_deg = lon_deg;
  if (right_m != 0.0) {
    earth.Direct(lat_deg, lon_deg, azimuth_deg + 90.0, right_m, lat2_deg, lon2_deg);
  }
  return {lat2_deg * kDegToRad, lon2_deg * kDegToRad, profile_.elevation_m(along_m) + up_m};
}

Eigen::Vector3d RunwayFrame::scene(double along_m, double right_m, double up_m) const {
  return scene_->position_scene_m(geodetic(along_m, right_m, up_m));
}

Eigen::Vector3d RunwayFrame::up_scene(double along_m, double right_m) const {
  const GeodeticPosition p = geodetic(along_m, right_m, 0.0);
  return scene_->up_scene(p.lat_rad, p.lon_rad);
}

Eigen::Vector3d RunwayFrame::forward_scene(double along_m, double right_m) const {
  const Eigen::Vector3d up = up_scene(along_m, right_m);
  const Eigen::Vector3d d = scene(along_m + 1.0, right_m, 0.0) - scene(along_m, right_m, 0.0);
  return (d - d.dot(up) * up).normalized();
}

}  // namespace fedsim::visual
