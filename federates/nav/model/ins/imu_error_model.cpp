// IMU error model: fixed bias, scale factor and white noise (random walk).
#include "federates/nav/model/ins/imu_error_model.hpp"

#include "common/units/units.hpp"

#include <cmath>
#include <stdexcept>
#include <string>

namespace fedsim::nav {

namespace {

// Edge units of inertial data sheets, built from units.hpp's factors.
constexpr double kSecondsPerHour = 3600.0;
constexpr double kSqrtSecondsPerSqrtHour = 60.0;  // sqrt(3600 s)
constexpr double kMicroG = 1e-6 * units::kStandardGravityMps2;
constexpr double kDegPerHourToRadps = units::kDegToRad / kSecondsPerHour;
constexpr double kDegPerSqrtHourToRadPerSqrtS = units::kDegToRad / kSqrtSecondsPerSqrtHour;
constexpr double kMpsPerSqrtHourToMpsPerSqrtS = 1.0 / kSqrtSecondsPerSqrtHour;
constexpr double kMaxScaleFactor = 0.1;

void check_non_negative(double value, const char* field) {
  if (!std::isfinite(value) || value < 0.0) {
    throw std::invalid_argument(std::string("IMU error figure ") + field + " = " +
                                std::to_string(value) + " must be finite and >= 0");
  }
}

void check_finite_vector(const Eigen::Vector3d& v, const char* field, double limit) {
  for (int i = 0; i < 3; ++i) {
    if (!std::isfinite(v[i]) || std::abs(v[i]) > limit) {
      throw std::invalid_argument(std::string("IMU error ") + field + "[" + std::to_string(i) +
                                  "] = " + std::to_string(v[i]) +
                                  " is not finite or beyond +-" + std::to_string(limit));
    }
  }
}

}  // namespace

ImuErrorSpec ImuErrorSpec::navigation_grade() {
  ImuErrorSpec spec;
  spec.accel_bias_mps2 = 50.0 * kMicroG;
  spec.accel_scale_factor = 100e-6;
  spec.velocity_random_walk_mps_per_sqrt_s = 20.0 * kMicroG;  // 20 ug/sqrt(Hz) = 0.012 m/s/sqrt(h)
  spec.gyro_bias_radps = 0.01 * kDegPerHourToRadps;
  spec.gyro_scale_factor = 10e-6;
  spec.angle_random_walk_rad_per_sqrt_s = 0.002 * kDegPerSqrtHourToRadPerSqrtS;
  return spec;
}

ImuErrorSpec ImuErrorSpec::tactical_grade() {
  ImuErrorSpec spec;
  spec.accel_bias_mps2 = 1000.0 * kMicroG;
  spec.accel_scale_factor = 300e-6;
  spec.velocity_random_walk_mps_per_sqrt_s = 0.06 * kMpsPerSqrtHourToMpsPerSqrtS;
  spec.gyro_bias_radps = 1.0 * kDegPerHourToRadps;
  spec.gyro_scale_factor = 150e-6;
  spec.angle_random_walk_rad_per_sqrt_s = 0.1 * kDegPerSqrtHourToRadPerSqrtS;
  return spec;
}

void ImuErrorSpec::check() const {
  check_non_negative(accel_bias_mps2, "accel_bias_mps2");
  check_non_negative(accel_scale_factor, "accel_scale_factor");
  check_non_negative(velocity_random_walk_mps_per_sqrt_s, "velocity_random_walk_mps_per_sqrt_s");
  check_non_negative(gyro_bias_radps, "gyro_bias_radps");
  check_non_negative(gyro_scale_factor, "gyro_scale_factor");
  check_non_negative(angle_random_walk_rad_per_sqrt_s, "angle_random_walk_rad_per_sqrt_s");
  if (accel_scale_factor > kMaxScaleFactor || gyro_scale_factor > kMaxScaleFactor) {
    throw std::invalid_argument("IMU scale-factor sigma beyond 0.1 (10 %)");
  }
}

ImuErrors ImuErrors::sample(const ImuErrorSpec& spec, std::uint64_t seed) {
  spec.check();
  std::mt19937_64 generator(seed);
  std::normal_distribution<double> unit_normal(0.0, 1.0);
  auto draw = [&](double sigma) {
    Eigen::Vector3d v;
    for (int i = 0; i < 3; ++i) v[i] = sigma * unit_normal(generator);
    return v;
  };
  ImuErrors errors;
  errors.accel_bias_body_mps2 = draw(spec.accel_bias_mps2);
  errors.accel_scale_factor_body = draw(spec.accel_scale_factor);
  errors.gyro_bias_body_radps = draw(spec.gyro_bias_radps);
  errors.gyro_scale_factor_body = draw(spec.gyro_scale_factor);
  errors.velocity_random_walk_mps_per_sqrt_s = spec.velocity_random_walk_mps_per_sqrt_s;
  errors.angle_random_walk_rad_per_sqrt_s = spec.angle_random_walk_rad_per_sqrt_s;
  return errors;
}

void ImuErrors::check() const {
  check_finite_vector(accel_bias_body_mps2, "accel_bias_body_mps2", kMaxSpecificForceMps2);
  check_finite_vector(accel_scale_factor_body, "accel_scale_factor_body", kMaxScaleFactor);
  check_finite_vector(gyro_bias_body_radps, "gyro_bias_body_radps", kMaxAngularRateRadps);
  check_finite_vector(gyro_scale_factor_body, "gyro_scale_factor_body", kMaxScaleFactor);
  check_non_negative(velocity_random_walk_mps_per_sqrt_s, "velocity_random_walk_mps_per_sqrt_s");
  check_non_negative(angle_random_walk_rad_per_sqrt_s, "angle_random_walk_rad_per_sqrt_s");
}

ImuErrorModel::ImuErrorModel(const ImuErrors& errors, std::uint64_t noise_seed)
    : errors_(errors), generator_(noise_seed) {
  errors_.check();
}

Eigen::Vector3d ImuErrorModel::white_noise(double density, double dt_s) {
  if (density == 0.0) return Eigen::Vector3d::Zero();
  // The mean of white noise of density N over dt has standard deviation N / sqrt(dt).
  const double sigma = density / std::sqrt(dt_s);
  Eigen::Vector3d v;
  for (int i = 0; i < 3; ++i) v[i] = sigma * unit_normal_(generator_);
  return v;
}

ImuSample ImuErrorModel::measure(const ImuSample& truth, double dt_s) {
  if (!std::isfinite(dt_s) || dt_s <= 0.0) {
    throw std::invalid_argument("ImuErrorModel::measure: dt_s = " + std::to_string(dt_s) +
                                " must be finite and > 0");
  }
  check_imu_sample(truth, "ImuErrorModel::measure");
  ImuSample measured;
  measured.specific_force_body_mps2 =
      truth.specific_force_body_mps2 +
      errors_.accel_scale_factor_body.cwiseProduct(truth.specific_force_body_mps2) +
      errors_.accel_bias_body_mps2 +
      white_noise(errors_.velocity_random_walk_mps_per_sqrt_s, dt_s);
  measured.omega_body_radps = truth.omega_body_radps +
                              errors_.gyro_scale_factor_body.cwiseProduct(truth.omega_body_radps) +
                              errors_.gyro_bias_body_radps +
                              white_noise(errors_.angle_random_walk_rad_per_sqrt_s, dt_s);
  return measured;
}

}  // namespace fedsim::nav
