// Circular Keplerian GPS orbits with J2 nodal regression and the earth's rotation.
#include "federates/nav/model/gps/gps_constellation.hpp"

#include "common/geodesy/wgs84.hpp"
#include "common/units/units.hpp"
#include "federates/nav/model/gps/gps_constellation_data.hpp"

#include <Eigen/Geometry>

#include <cmath>
#include <stdexcept>

namespace fedsim::nav {

namespace {

constexpr double kMaxTimeFromEpochS = 100.0 * 365.25 * 86400.0;

void check_orbit(const GpsOrbit& o) {
  const bool finite = std::isfinite(o.raan_at_epoch_rad) &&
                      std::isfinite(o.argument_of_latitude_at_epoch_rad) &&
                      std::isfinite(o.inclination_rad) && std::isfinite(o.semi_major_axis_m);
  if (!finite || o.semi_major_axis_m <= wgs84::kSemiMajorAxisM || o.inclination_rad < 0.0 ||
      o.inclination_rad > units::kPi) {
    throw std::invalid_argument("GpsConstellation: orbit '" + o.slot +
                                "' is not finite, inside the earth or of inclination outside "
                                "[0, pi]");
  }
}

double mean_motion_radps(const GpsOrbit& o) {
  return std::sqrt(wgs84::kGmM3ps2 / (o.semi_major_axis_m * o.semi_major_axis_m *
                                      o.semi_major_axis_m));
}

}  // namespace

void check_gps_time(double time_since_epoch_s, const char* origin) {
  if (!std::isfinite(time_since_epoch_s) || std::abs(time_since_epoch_s) > kMaxTimeFromEpochS) {
    throw std::invalid_argument(std::string(origin) + ": time_since_epoch_s = " +
                                std::to_string(time_since_epoch_s) +
                                " is not finite or beyond 100 years from the epoch");
  }
}

GpsConstellation GpsConstellation::baseline_24(bool j2_nodal_regression) {
  std::vector<GpsOrbit> orbits;
  for (const gps_sps::SlotAssignment& s : gps_sps::kBaselineSlots) {
    orbits.push_back({s.slot, s.raan_deg * units::kDegToRad,
                      s.argument_of_latitude_deg * units::kDegToRad,
                      gps_sps::kInclinationDeg * units::kDegToRad,
                      gps_sps::kSemiMajorAxisKm * 1000.0});  // km -> m
  }
  return GpsConstellation(std::move(orbits), j2_nodal_regression);
}

GpsConstellation::GpsConstellation(std::vector<GpsOrbit> orbits, bool j2_nodal_regression)
    : orbits_(std::move(orbits)), j2_nodal_regression_(j2_nodal_regression) {
  for (const GpsOrbit& o : orbits_) check_orbit(o);
}

double GpsConstellation::orbital_period_s(std::size_t index) const {
  return units::kTwoPi / mean_motion_radps(orbit(index));
}

double GpsConstellation::raan_rate_radps(std::size_t index) const {
  if (!j2_nodal_regression_) return 0.0;
  const GpsOrbit& o = orbit(index);
  const double ratio = wgs84::kSemiMajorAxisM / o.semi_major_axis_m;
  return -1.5 * mean_motion_radps(o) * wgs84::kJ2 * ratio * ratio * std::cos(o.inclination_rad);
}

double GpsConstellation::greenwich_hour_angle_rad(double time_since_epoch_s) {
  const double at_epoch_rad = gps_sps::kGreenwichHourAngleAtEpochHours *
                              gps_sps::kDegreesPerHourOfAngle * units::kDegToRad;
  return std::fmod(at_epoch_rad + wgs84::kEarthRateRadps * time_since_epoch_s, units::kTwoPi);
}

Eigen::Vector3d GpsConstellation::position_eci_m(std::size_t index,
                                                 double time_since_epoch_s) const {
  check_gps_time(time_since_epoch_s, "GpsConstellation::position_eci_m");
  const GpsOrbit& o = orbit(index);
  const double u = o.argument_of_latitude_at_epoch_rad + mean_motion_radps(o) * time_since_epoch_s;
  const double raan = o.raan_at_epoch_rad + raan_rate_radps(index) * time_since_epoch_s;
  const Eigen::Vector3d in_plane(o.semi_major_axis_m * std::cos(u),
                                 o.semi_major_axis_m * std::sin(u), 0.0);
  // Perifocal-like (node-referenced) frame to ECI: rotate by i about x, then by RAAN about z.
  return Eigen::AngleAxisd(raan, Eigen::Vector3d::UnitZ()) *
         (Eigen::AngleAxisd(o.inclination_rad, Eigen::Vector3d::UnitX()) * in_plane);
}

Eigen::Vector3d GpsConstellation::position_ecef_m(std::size_t index,
                                                  double time_since_epoch_s) const {
  // ECEF = R3(theta_G) ECI: a vector fixed in inertial space turns backwards in the earth frame.
  return Eigen::AngleAxisd(-greenwich_hour_angle_rad(time_since_epoch_s),
                           Eigen::Vector3d::UnitZ()) *
         position_eci_m(index, time_since_epoch_s);
}

}  // namespace fedsim::nav
