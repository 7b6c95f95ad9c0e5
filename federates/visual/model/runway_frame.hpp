// The local coordinates of one runway end: `along` from the landing threshold in the landing
// direction (negative: the approach side), `right` to the right of the landing direction, `up`
// above the runway's longitudinal profile. Mapped to the scene exactly: along the geodesic that
// leaves the threshold at the landing heading, then along the geodesic at right angles
// (GeographicLib), then up along the ellipsoid normal. The profile is linear between the
// elevations of the two published runway ends and level beyond them.
#pragma once

#include "visual/model/scene_frame.hpp"

#include <Eigen/Core>

namespace fedsim::visual {

struct RunwayProfile {
  double start_along_m = 0.0;      // where start_elevation_m holds (this end's runway end) [m]
  double start_elevation_m = 0.0;  // [m MSL]
  double end_along_m = 1.0;        // the opposite runway end [m]
  double end_elevation_m = 0.0;    // [m MSL]
  double elevation_m(double along_m) const;
};

class RunwayFrame {
 public:
  /// threshold: the landing threshold (its height ignored: the profile gives heights).
  RunwayFrame(const SceneFrame& scene, double threshold_lat_rad, double threshold_lon_rad,
              double heading_true_rad, const RunwayProfile& profile);

  GeodeticPosition geodetic(double along_m, double right_m, double up_m) const;
  Eigen::Vector3d scene(double along_m, double right_m, double up_m) const;
  /// Unit local vertical at a runway point, scene axes.
  Eigen::Vector3d up_scene(double along_m, double right_m) const;
  /// Unit horizontal direction of increasing `along` at a runway point, scene axes.
  Eigen::Vector3d forward_scene(double along_m, double right_m) const;
  const RunwayProfile& profile() const { return profile_; }
  double heading_true_rad() const { return heading_true_rad_; }

 private:
  const SceneFrame* scene_;
  double lat_rad_;
  double lon_rad_;
  double heading_true_rad_;
  RunwayProfile profile_;
};

}  // namespace fedsim::visual
