// The scene frame S: the local tangent plane at the airport reference point, axes north, east,
// down (NED, docs/frames.md) along the ellipsoid normal there, origin at the reference point at
// the ground elevation. Positions map into it exactly (geodetic -> ECEF -> rotate into NED at the
// origin; common/geodesy), so the earth's curvature is kept: a point 4 km away on the ellipsoid
// lies 1.25 m below the plane, and the horizon dips as it should.
//
// The ground is drawn as the sphere that osculates the ellipsoid at the origin (Gaussian radius
// sqrt(M N), plus the ground elevation), centred on the scene's +z axis: within 20 km it differs
// from the ellipsoid by less than 0.2 m.
#pragma once

#include "common/geodesy/wgs84.hpp"

#include <Eigen/Core>

namespace fedsim::visual {

class SceneFrame {
 public:
  /// `origin`: the airport reference point, its height the ground elevation (MSL taken as the
  /// ellipsoid, as everywhere in fedsim). Throws std::invalid_argument for a bad position.
  explicit SceneFrame(const GeodeticPosition& origin);

  const GeodeticPosition& origin() const { return origin_; }

  /// Position of a geodetic point in S [m].
  Eigen::Vector3d position_scene_m(const GeodeticPosition& point) const;
  /// The geodetic position of a scene point (inverse of position_scene_m).
  GeodeticPosition geodetic(const Eigen::Vector3d& position_scene_m) const;
  /// Rotation taking components in the local NED frame at (lat, lon) to scene components.
  Eigen::Matrix3d scene_from_local_ned(double lat_rad, double lon_rad) const;
  /// Unit local vertical (up) at a geodetic point, in scene axes.
  Eigen::Vector3d up_scene(double lat_rad, double lon_rad) const;

  /// Radius of the ground sphere [m] (osculating sphere at the origin at the ground elevation);
  /// its centre is at (0, 0, ground_radius_m()) in S.
  double ground_radius_m() const { return ground_radius_m_; }

 private:
  GeodeticPosition origin_;
  Eigen::Vector3d origin_ecef_m_;
  Eigen::Matrix3d scene_from_ecef_;
  double ground_radius_m_;
};

}  // namespace fedsim::visual
