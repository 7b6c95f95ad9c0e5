// Flat and rotating WGS-84 earth models for the equations of motion.
#include "flight/model/dynamics/earth_model.hpp"
#include "common/units/units.hpp"

#include <Eigen/Geometry>

#include <cmath>
#include <stdexcept>

namespace fedsim::flight {

namespace {
constexpr double kMaxOriginLatRad = 89.9 * units::kPi / 180.0;
}  // namespace

EarthModel::EarthModel(EarthModelConfig config) : config_(config) {
  if (config_.kind == EarthModelKind::kFlat) {
    if (!(config_.flat_gravity_mps2 > 0.0) || !std::isfinite(config_.flat_gravity_mps2)) {
      throw std::invalid_argument("flat earth: gravity must be positive and finite");
    }
    if (!(std::abs(config_.origin_lat_rad) <= kMaxOriginLatRad) ||
        !std::isfinite(config_.origin_lon_rad)) {
      throw std::invalid_argument("flat earth: origin must be finite and not within 0.1 deg of a pole");
    }
  }
  origin_meridian_radius_m_ = Wgs84::meridian_radius_m(config_.origin_lat_rad);
  origin_parallel_radius_m_ =
      Wgs84::prime_vertical_radius_m(config_.origin_lat_rad) * std::cos(config_.origin_lat_rad);
}

Eigen::Vector3d EarthModel::gravitation(const Eigen::Vector3d& position_m) const {
  if (config_.kind == EarthModelKind::kFlat) return {0.0, 0.0, config_.flat_gravity_mps2};
  return Wgs84::gravitation_ecef(position_m);
}

Eigen::Vector3d EarthModel::free_fall_acceleration(const Eigen::Vector3d& position_m,
                                                   const Eigen::Vector3d& velocity_mps) const {
  if (config_.kind == EarthModelKind::kFlat) return gravitation(position_m);
  const Eigen::Vector3d w = Wgs84::earth_rate_ecef();
  return Wgs84::gravitation_ecef(position_m) - 2.0 * w.cross(velocity_mps) -
         w.cross(w.cross(position_m));
}

Eigen::Vector3d EarthModel::frame_rate_radps() const {
  if (config_.kind == EarthModelKind::kFlat) return Eigen::Vector3d::Zero();
  return Wgs84::earth_rate_ecef();
}

GeodeticPosition EarthModel::geodetic(const Eigen::Vector3d& position_m) const {
  if (config_.kind == EarthModelKind::kWgs84) return Wgs84::geodetic_from_ecef(position_m);
  return {config_.origin_lat_rad + position_m.x() / origin_meridian_radius_m_,
          config_.origin_lon_rad + position_m.y() / origin_parallel_radius_m_, -position_m.z()};
}

Eigen::Vector3d EarthModel::position_from_geodetic(const GeodeticPosition& geodetic) const {
  if (config_.kind == EarthModelKind::kWgs84) return Wgs84::ecef_from_geodetic(geodetic);
  return {(geodetic.lat_rad - config_.origin_lat_rad) * origin_meridian_radius_m_,
          (geodetic.lon_rad - config_.origin_lon_rad) * origin_parallel_radius_m_,
          -geodetic.alt_m};
}

Eigen::Vector3d EarthModel::ecef(const Eigen::Vector3d& position_m) const {
  if (config_.kind == EarthModelKind::kWgs84) return position_m;
  return Wgs84::ecef_from_geodetic(geodetic(position_m));
}

Eigen::Matrix3d EarthModel::ned_from_reference(const GeodeticPosition& at) const {
  if (config_.kind == EarthModelKind::kFlat) return Eigen::Matrix3d::Identity();
  return Wgs84::ned_from_ecef(at.lat_rad, at.lon_rad);
}

}  // namespace fedsim::flight
