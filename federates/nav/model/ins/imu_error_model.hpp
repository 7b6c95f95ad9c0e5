// Sensor errors of a strapdown IMU (seed 6.10.3; Titterton & Weston, Strapdown Inertial
// Navigation Technology, 2nd ed. 2004, ch. 4-6 and 8 (gyro and accelerometer errors) and
// Groves, Principles of GNSS, Inertial, and Multisensor Integrated Navigation Systems, 2nd ed.
// 2013, section 4.4).
//
// Error model, per axis i of the body frame, for the mean outputs over an interval dt:
//   f_meas_i     = (1 + s_a_i) f_i     + b_a_i + w_a_i,   w_a_i ~ N(0, VRW^2 / dt)
//   omega_meas_i = (1 + s_g_i) omega_i + b_g_i + w_g_i,   w_g_i ~ N(0, ARW^2 / dt)
// b: fixed (turn-on) bias [m/s^2, rad/s]; s: scale-factor error [-] (1e-6 = 1 ppm);
// VRW, ARW: velocity and angle random walk, the white-noise density of the output, so that the
// integrated output (velocity, angle) wanders with standard deviation VRW sqrt(t), ARW sqrt(t)
// whatever the interval [m/s/sqrt(s), rad/sqrt(s)]. Misalignment, g-sensitivity, bias
// instability (flicker) and quantisation are not modelled.
//
// Randomness: std::mt19937_64 with an explicit seed (turn-on errors drawn from one seed, the
// noise from another); same seeds, same outputs.
#pragma once

#include "federates/nav/model/ins/imu_sample.hpp"

#include <Eigen/Core>

#include <cstdint>
#include <random>

namespace fedsim::nav {

/// 1-sigma error figures of a class of IMU (per axis), SI.
struct ImuErrorSpec {
  double accel_bias_mps2 = 0.0;                     // fixed accelerometer bias [m/s^2]
  double accel_scale_factor = 0.0;                  // accelerometer scale-factor error [-]
  double velocity_random_walk_mps_per_sqrt_s = 0.0; // VRW [m/s/sqrt(s)]
  double gyro_bias_radps = 0.0;                     // fixed gyro bias [rad/s]
  double gyro_scale_factor = 0.0;                   // gyro scale-factor error [-]
  double angle_random_walk_rad_per_sqrt_s = 0.0;    // ARW [rad/sqrt(s)]

  /// A navigation-grade (aviation-grade, ring-laser-gyro class, ~1 nmi/h free inertial) unit:
  /// accelerometer bias 50 ug, scale factor 100 ppm, VRW 0.012 m/s/sqrt(h) (20 ug/sqrt(Hz));
  /// gyro bias 0.01 deg/h, scale factor 10 ppm, ARW 0.002 deg/sqrt(h).
  /// Representative of Groves (2013) section 4.4, Tables 4.1-4.2 (aviation grade: accelerometer
  /// bias 30-100 ug, gyro bias 0.001-0.01 deg/h) and El-Sheimy & Youssef, "Inertial sensors
  /// technologies for navigation applications", Satellite Navigation 1:2 (2020), Table 1
  /// (navigation grade: gyro drift < 0.01 deg/h, accelerometer bias < 100 ug).
  static ImuErrorSpec navigation_grade();
  /// A tactical-grade (fibre-optic / small RLG class) unit: accelerometer bias 1 mg, scale factor
  /// 300 ppm, VRW 0.06 m/s/sqrt(h) (100 ug/sqrt(Hz)); gyro bias 1 deg/h, scale factor 150 ppm,
  /// ARW 0.1 deg/sqrt(h). Groves (2013) Tables 4.1-4.2 (tactical grade: accelerometer bias
  /// 1-10 mg, gyro bias 1-100 deg/h); El-Sheimy & Youssef (2020) Table 1 (gyro drift 1-10 deg/h).
  static ImuErrorSpec tactical_grade();

  /// Throws std::invalid_argument if a figure is negative or not finite.
  void check() const;
};

/// The errors of one particular unit (realised per axis, body frame) plus its noise densities.
struct ImuErrors {
  Eigen::Vector3d accel_bias_body_mps2 = Eigen::Vector3d::Zero();
  Eigen::Vector3d accel_scale_factor_body = Eigen::Vector3d::Zero();  // [-]
  double velocity_random_walk_mps_per_sqrt_s = 0.0;
  Eigen::Vector3d gyro_bias_body_radps = Eigen::Vector3d::Zero();
  Eigen::Vector3d gyro_scale_factor_body = Eigen::Vector3d::Zero();  // [-]
  double angle_random_walk_rad_per_sqrt_s = 0.0;

  /// A perfect unit (all zero).
  static ImuErrors none() { return {}; }
  /// One unit drawn from a class: each axis's bias and scale factor ~ N(0, sigma^2) from a
  /// std::mt19937_64 seeded with `seed`; the noise densities are the spec's.
  static ImuErrors sample(const ImuErrorSpec& spec, std::uint64_t seed);

  /// Throws std::invalid_argument if a value is not finite, a density is negative, or a scale
  /// factor is beyond +-0.1 (10 %, not an inertial sensor).
  void check() const;
};

/// Corrupts true IMU samples with a unit's errors.
/// Input: the true mean specific force and rate over dt (body, SI) and dt [s] > 0.
/// Output: the measured sample (same units and frame).
class ImuErrorModel {
 public:
  explicit ImuErrorModel(const ImuErrors& errors = ImuErrors::none(),
                         std::uint64_t noise_seed = 0);

  ImuSample measure(const ImuSample& truth, double dt_s);

  const ImuErrors& errors() const { return errors_; }

 private:
  Eigen::Vector3d white_noise(double density, double dt_s);

  ImuErrors errors_;
  std::mt19937_64 generator_;
  std::normal_distribution<double> unit_normal_{0.0, 1.0};
};

}  // namespace fedsim::nav
