// The inertial navigation system: sensor errors, sub-stepped mechanisation, baro damping.
#include "federates/nav/model/ins/inertial_navigation_system.hpp"

#include "federates/nav/model/ins/navigation_earth.hpp"

#include <cmath>
#include <stdexcept>
#include <string>

namespace fedsim::nav {

namespace {

constexpr double kMaxIntegrationRateHz = 10000.0;
constexpr double kMaxStepS = 60.0;

const InsConfig& checked(const InsConfig& config) {
  config.check();
  return config;
}

NavigationState aligned_state(const NavigationState& truth, const InitialErrors& e) {
  return perturbed_state(truth, e.position_ned_m, e.velocity_ned_mps, e.tilt_ned_rad);
}

}  // namespace

void InsConfig::check() const {
  if (!std::isfinite(integration_rate_hz) || integration_rate_hz <= 0.0 ||
      integration_rate_hz > kMaxIntegrationRateHz) {
    throw std::invalid_argument("InsConfig: integration_rate_hz = " +
                                std::to_string(integration_rate_hz) + " must be in (0, 10000]");
  }
  // Constructing the loop checks its time constant.
  BaroInertialLoop loop(baro_loop_time_constant_s);
  imu_errors.check();
}

InertialNavigationSystem::InertialNavigationSystem(const InsConfig& config,
                                                   const NavigationState& alignment_truth,
                                                   const InitialErrors& initial_errors)
    : config_(checked(config)),
      imu_(config.imu_errors, config.noise_seed),
      mechanisation_(aligned_state(alignment_truth, initial_errors)),
      baro_loop_(config.baro_loop_time_constant_s) {}

void InertialNavigationSystem::step(const ImuSample& true_imu, double dt_s,
                                    std::optional<double> baro_height_m) {
  if (!std::isfinite(dt_s) || dt_s <= 0.0 || dt_s > kMaxStepS) {
    throw std::invalid_argument("InertialNavigationSystem::step: dt_s = " + std::to_string(dt_s) +
                                " must be in (0, 60] s");
  }
  check_imu_sample(true_imu, "InertialNavigationSystem::step");
  if (baro_height_m && (!std::isfinite(*baro_height_m) || *baro_height_m < kMinHeightM ||
                        *baro_height_m > kMaxHeightM)) {
    throw std::invalid_argument("InertialNavigationSystem::step: baro_height_m = " +
                                std::to_string(*baro_height_m) + " not finite or out of range");
  }
  // Sub-steps at (at least) the stated rate; the tolerance keeps dt * rate = 1 at one step.
  const auto sub_steps =
      static_cast<long>(std::max(1.0, std::ceil(dt_s * config_.integration_rate_hz - 1e-9)));
  const double dt_sub = dt_s / static_cast<double>(sub_steps);
  for (long i = 0; i < sub_steps; ++i) sub_step(true_imu, dt_sub, baro_height_m);
  time_s_ += dt_s;
}

void InertialNavigationSystem::sub_step(const ImuSample& true_imu, double dt_s,
                                        std::optional<double> baro_height_m) {
  const ImuSample measured = imu_.measure(true_imu, dt_s);
  VerticalChannelCorrection vertical;
  vertical_channel_aided_ =
      config_.vertical_channel == VerticalChannel::kBaroDamped && baro_height_m.has_value();
  if (vertical_channel_aided_) {
    const NavigationState& s = mechanisation_.state();
    const LocalRadii r = local_radii(s.position.lat_rad, s.position.alt_m);
    const double mean_radius_m =
        std::sqrt(r.meridian_plus_height_m * r.transverse_plus_height_m);
    vertical = baro_loop_.step(s.position.alt_m, *baro_height_m, gravity_ned(s.position).norm(),
                               mean_radius_m, dt_s);
  }
  mechanisation_.update(measured, dt_s, vertical);
}

InsSolution InertialNavigationSystem::solution() const {
  InsSolution out;
  out.time_s = time_s_;
  out.state = mechanisation_.state();
  out.position_ecef_m = Wgs84::ecef_from_geodetic(out.state.position);
  out.euler = euler_from_quaternion(out.state.q_ned_from_body);
  out.vertical_channel_aided = vertical_channel_aided_;
  out.baro_accel_bias_estimate_down_mps2 = baro_loop_.accel_bias_estimate_down_mps2();
  return out;
}

NavigationErrors InertialNavigationSystem::errors_against(const NavigationState& truth) const {
  check_navigation_state(truth, "InertialNavigationSystem::errors_against truth");
  return navigation_errors(mechanisation_.state(), truth);
}

ImuSample imu_from_kinematics(const NavigationState& truth,
                              const Eigen::Vector3d& acceleration_ned_mps2,
                              const Eigen::Vector3d& omega_body_wrt_ned_radps) {
  check_navigation_state(truth, "imu_from_kinematics truth");
  if (!acceleration_ned_mps2.allFinite() || !omega_body_wrt_ned_radps.allFinite()) {
    throw std::invalid_argument("imu_from_kinematics: acceleration or rate not finite");
  }
  const double lat = truth.position.lat_rad;
  const Eigen::Vector3d omega_ie = earth_rate_ned(lat);
  const Eigen::Vector3d omega_en =
      transport_rate_ned(lat, truth.position.alt_m, truth.velocity_ned_mps);
  const Eigen::Quaterniond body_from_ned = truth.q_ned_from_body.normalized().conjugate();
  ImuSample sample;
  sample.specific_force_body_mps2 =
      body_from_ned * (acceleration_ned_mps2 +
                       (2.0 * omega_ie + omega_en).cross(truth.velocity_ned_mps) -
                       gravity_ned(truth.position));
  sample.omega_body_radps = omega_body_wrt_ned_radps + body_from_ned * (omega_ie + omega_en);
  check_imu_sample(sample, "imu_from_kinematics");
  return sample;
}

}  // namespace fedsim::nav
