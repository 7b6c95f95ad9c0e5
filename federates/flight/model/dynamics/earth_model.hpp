// The earth under the rigid body: a flat, non-rotating earth or the rotating WGS-84 ellipsoid.
#pragma once

#include <Eigen/Core>
#include "common/units/units.hpp"

#include "common/geodesy/wgs84.hpp"

namespace fedsim::flight {

enum class EarthModelKind {
  /// NED axes at the origin (lat0, lon0, h = 0) are inertial; gravity is a constant g along
  /// +down. The reference frame of the state is that NED frame.
  kFlat,
  /// WGS-84 ellipsoid rotating at 7.292115e-5 rad/s with J2 gravitation. The state is held in
  /// ECEF: position, velocity relative to the earth and attitude relative to ECEF; the equations
  /// carry the Coriolis and centripetal terms (seed 3.11).
  kWgs84,
};

struct EarthModelConfig {
  EarthModelKind kind = EarthModelKind::kWgs84;
  double flat_gravity_mps2 = units::kStandardGravityMps2;  // flat earth only
  double origin_lat_rad = 0.0;         // flat earth only: where the NED frame is pinned
  double origin_lon_rad = 0.0;
};

/// Everything the equations of motion need to know about the earth. Value type, no allocation.
class EarthModel {
 public:
  /// Throws std::invalid_argument for a non-finite or non-positive flat gravity or a flat-earth
  /// origin within 0.1 deg of a pole (the local east axis is undefined there).
  explicit EarthModel(EarthModelConfig config = {});

  EarthModelKind kind() const { return config_.kind; }
  const EarthModelConfig& config() const { return config_; }

  /// Acceleration of a free particle relative to the reference frame, reference axes: gravity
  /// plus, on the rotating earth, the Coriolis -2 W x v and centripetal -W x (W x r) terms.
  Eigen::Vector3d free_fall_acceleration(const Eigen::Vector3d& position_m,
                                         const Eigen::Vector3d& velocity_mps) const;
  /// Gravitational attraction alone (no rotation terms), reference axes.
  Eigen::Vector3d gravitation(const Eigen::Vector3d& position_m) const;
  /// Angular velocity of the reference frame relative to inertial space, reference axes.
  Eigen::Vector3d frame_rate_radps() const;

  /// Geodetic position of a reference-frame position. On the flat earth the height is -down and
  /// lat/lon follow from north/east through the radii of curvature at the origin (seed eqs
  /// 3.51-3.52 integrated at constant radius).
  GeodeticPosition geodetic(const Eigen::Vector3d& position_m) const;
  Eigen::Vector3d position_from_geodetic(const GeodeticPosition& geodetic) const;
  /// ECEF position (m) of a reference-frame position.
  Eigen::Vector3d ecef(const Eigen::Vector3d& position_m) const;
  /// Rotation from reference-frame axes to the local NED axes at a geodetic position.
  Eigen::Matrix3d ned_from_reference(const GeodeticPosition& at) const;

 private:
  EarthModelConfig config_;
  double origin_meridian_radius_m_ = 0.0;
  double origin_parallel_radius_m_ = 0.0;  // prime vertical radius * cos(lat0)
};

}  // namespace fedsim::flight
