// The GPS receiver: measure, solve, report validity.
#include "federates/nav/model/gps/gps_receiver.hpp"

#include "federates/nav/model/gps/gps_constellation_data.hpp"

#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>

namespace fedsim::nav {

namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

GpsFix invalid_fix(FixStatus status, int visible) {
  GpsFix fix;
  fix.valid = false;
  fix.status = status;
  fix.satellites_visible = visible;
  fix.position_ecef_m = Eigen::Vector3d::Constant(kNaN);
  fix.position = {kNaN, kNaN, kNaN};
  fix.clock_bias_s = kNaN;
  fix.dop = {kNaN, kNaN, kNaN, kNaN, kNaN, Eigen::Matrix4d::Constant(kNaN)};
  fix.residual_rms_m = kNaN;
  return fix;
}

const GpsReceiverConfig& checked(const GpsReceiverConfig& config) {
  config.check();
  return config;
}

}  // namespace

void GpsReceiverConfig::check() const {
  pseudoranges.check();
  if (!std::isfinite(clock_bias_s) || std::abs(clock_bias_s) > 0.1) {
    throw std::invalid_argument("GpsReceiverConfig: clock_bias_s = " + std::to_string(clock_bias_s) +
                                " must be finite and within +-0.1 s");
  }
  if (!std::isfinite(clock_drift_sps) || std::abs(clock_drift_sps) > 1e-5) {
    throw std::invalid_argument("GpsReceiverConfig: clock_drift_sps = " +
                                std::to_string(clock_drift_sps) +
                                " must be finite and within +-1e-5 s/s");
  }
}

GpsReceiver::GpsReceiver(GpsConstellation constellation, const GpsReceiverConfig& config)
    : constellation_(std::move(constellation)),
      config_(checked(config)),
      pseudoranges_(config.pseudoranges) {}

double GpsReceiver::true_clock_bias_s(double time_since_epoch_s) const {
  return config_.clock_bias_s + config_.clock_drift_sps * time_since_epoch_s;
}

GpsFix GpsReceiver::update(double time_since_epoch_s, const Eigen::Vector3d& true_position_ecef_m,
                           bool denied) {
  check_gps_time(time_since_epoch_s, "GpsReceiver::update");
  check_receiver_position(true_position_ecef_m, "GpsReceiver::update");
  if (denied) return invalid_fix(FixStatus::kDenied, 0);

  const std::vector<Pseudorange> measured =
      pseudoranges_.measure(constellation_, time_since_epoch_s, true_position_ecef_m,
                            true_clock_bias_s(time_since_epoch_s));
  const int visible = static_cast<int>(measured.size());
  const Eigen::Vector3d start = last_valid_ ? last_valid_->position_ecef_m : Eigen::Vector3d::Zero();
  const double start_clock_m = last_valid_ ? last_valid_->clock_bias_m : 0.0;
  LeastSquaresFix solution = solve_least_squares(measured, start, start_clock_m, config_.solver);
  if (solution.status == FixStatus::kNotConverged && last_valid_) {
    // The last fix may be far away after a long outage: start again from the earth's centre.
    solution = solve_least_squares(measured, Eigen::Vector3d::Zero(), 0.0, config_.solver);
  }
  if (solution.status != FixStatus::kValid) return invalid_fix(solution.status, visible);

  last_valid_ = solution;
  GpsFix fix;
  fix.valid = true;
  fix.status = FixStatus::kValid;
  fix.satellites_visible = visible;
  fix.satellites_used = visible;
  fix.position_ecef_m = solution.position_ecef_m;
  fix.position = Wgs84::geodetic_from_ecef(solution.position_ecef_m);
  fix.clock_bias_s = solution.clock_bias_m / gps_sps::kSpeedOfLightMps;
  fix.dop = solution.dop;
  fix.residual_rms_m = solution.residual_rms_m;
  fix.iterations = solution.iterations;
  return fix;
}

}  // namespace fedsim::nav
