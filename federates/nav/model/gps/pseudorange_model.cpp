// Pseudoranges with clock bias, optional atmospheric biases and seeded noise.
#include "federates/nav/model/gps/pseudorange_model.hpp"

#include "common/geodesy/wgs84.hpp"
#include "common/units/units.hpp"
#include "federates/nav/model/gps/gps_constellation_data.hpp"

#include <cmath>
#include <stdexcept>
#include <string>

namespace fedsim::nav {

namespace {

void check_range(double value, double min, double max, const char* field, bool max_open = false) {
  if (!std::isfinite(value) || value < min || value > max || (max_open && value == max)) {
    throw std::invalid_argument(std::string("PseudorangeConfig: ") + field + " = " +
                                std::to_string(value) + " must be in [" + std::to_string(min) +
                                ", " + std::to_string(max) + (max_open ? ")" : "]"));
  }
}

constexpr double kMaxClockBiasS = 1.0;  // a receiver clock off by more than 1 s is a data error

}  // namespace

void PseudorangeConfig::check() const {
  check_range(mask_angle_rad, 0.0, units::kHalfPi, "mask_angle_rad", true);
  check_range(noise_sigma_m, 0.0, 1000.0, "noise_sigma_m");
  check_range(troposphere_zenith_delay_m, 0.0, 10.0, "troposphere_zenith_delay_m");
  check_range(ionosphere_zenith_delay_m, 0.0, 100.0, "ionosphere_zenith_delay_m");
}

void check_receiver_position(const Eigen::Vector3d& receiver_ecef_m, const char* origin) {
  const double r = receiver_ecef_m.norm();
  if (!receiver_ecef_m.allFinite() || r < wgs84::kSemiMajorAxisM - 1.0e6 ||
      r > wgs84::kSemiMajorAxisM + 3.0e6) {
    throw std::invalid_argument(std::string(origin) +
                                ": receiver position is not finite or not within 1000 km below "
                                "to 3000 km above the earth's surface");
  }
}

double troposphere_mapping(double elevation_rad) {
  const double s = std::sin(elevation_rad);
  return 1.001 / std::sqrt(0.002001 + s * s);
}

double ionosphere_obliquity(double elevation_rad) {
  const double e_semicircles = elevation_rad / units::kPi;
  const double x = 0.53 - e_semicircles;
  return 1.0 + 16.0 * x * x * x;
}

PseudorangeModel::PseudorangeModel(const PseudorangeConfig& config)
    : config_(config), generator_(config.seed) {
  config_.check();
}

std::vector<std::size_t> PseudorangeModel::visible(const GpsConstellation& constellation,
                                                   double time_since_epoch_s,
                                                   const Eigen::Vector3d& receiver_ecef_m) const {
  check_receiver_position(receiver_ecef_m, "PseudorangeModel::visible");
  std::vector<std::size_t> out;
  for (std::size_t k = 0; k < constellation.size(); ++k) {
    const LookAngles look =
        look_angles(receiver_ecef_m, constellation.position_ecef_m(k, time_since_epoch_s));
    if (look.elevation_rad >= config_.mask_angle_rad) out.push_back(k);
  }
  return out;
}

std::vector<Pseudorange> PseudorangeModel::measure(const GpsConstellation& constellation,
                                                   double time_since_epoch_s,
                                                   const Eigen::Vector3d& receiver_ecef_m,
                                                   double clock_bias_s) {
  check_receiver_position(receiver_ecef_m, "PseudorangeModel::measure");
  if (!std::isfinite(clock_bias_s) || std::abs(clock_bias_s) > kMaxClockBiasS) {
    throw std::invalid_argument("PseudorangeModel::measure: clock_bias_s = " +
                                std::to_string(clock_bias_s) + " is not finite or beyond 1 s");
  }
  std::vector<Pseudorange> out;
  for (std::size_t k = 0; k < constellation.size(); ++k) {
    const Eigen::Vector3d sat = constellation.position_ecef_m(k, time_since_epoch_s);
    const LookAngles look = look_angles(receiver_ecef_m, sat);
    if (look.elevation_rad < config_.mask_angle_rad) continue;
    const double atmosphere_m =
        config_.troposphere_zenith_delay_m * troposphere_mapping(look.elevation_rad) +
        config_.ionosphere_zenith_delay_m * ionosphere_obliquity(look.elevation_rad);
    const double noise_m =
        config_.noise_sigma_m > 0.0 ? config_.noise_sigma_m * unit_normal_(generator_) : 0.0;
    out.push_back({k, sat,
                   look.range_m + gps_sps::kSpeedOfLightMps * clock_bias_s + atmosphere_m + noise_m,
                   look.elevation_rad, look.azimuth_rad});
  }
  return out;
}

}  // namespace fedsim::nav
