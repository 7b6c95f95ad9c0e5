// The IMU error model (bias, scale factor, random walk), its seeding, and the INS's vertical
// channel free and baro-damped, and its input checks.
#include "federates/nav/model/ins/imu_error_model.hpp"
#include "federates/nav/model/ins/inertial_navigation_system.hpp"
#include "federates/nav/model/ins/test/ins_test_support.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <stdexcept>

namespace fedsim::nav {
namespace {

using test::kDeg;

TEST(ImuErrorModel, BiasAndScaleFactorAreAppliedPerAxis) {
  ImuErrors errors;
  errors.accel_bias_body_mps2 = {0.01, -0.02, 0.03};
  errors.accel_scale_factor_body = {1e-3, 0.0, -2e-3};
  errors.gyro_bias_body_radps = {1e-5, 2e-5, -3e-5};
  errors.gyro_scale_factor_body = {0.0, 5e-4, 0.0};
  ImuErrorModel model(errors, 1);
  const ImuSample truth{{1.0, 2.0, -9.8}, {0.1, -0.2, 0.3}};
  const ImuSample m = model.measure(truth, 0.01);
  EXPECT_DOUBLE_EQ(m.specific_force_body_mps2.x(), 1.0 * 1.001 + 0.01);
  EXPECT_DOUBLE_EQ(m.specific_force_body_mps2.y(), 2.0 - 0.02);
  EXPECT_DOUBLE_EQ(m.specific_force_body_mps2.z(), -9.8 * 0.998 + 0.03);
  EXPECT_DOUBLE_EQ(m.omega_body_radps.x(), 0.1 + 1e-5);
  EXPECT_DOUBLE_EQ(m.omega_body_radps.y(), -0.2 * 1.0005 + 2e-5);
  EXPECT_DOUBLE_EQ(m.omega_body_radps.z(), 0.3 - 3e-5);
}

TEST(ImuErrorModel, GradesHaveTheStatedFigures) {
  const ImuErrorSpec nav = ImuErrorSpec::navigation_grade();
  const ImuErrorSpec tac = ImuErrorSpec::tactical_grade();
  EXPECT_NEAR(nav.gyro_bias_radps, 0.01 * kDeg / 3600.0, 1e-15);
  EXPECT_NEAR(nav.accel_bias_mps2, 50e-6 * 9.80665, 1e-12);
  EXPECT_NEAR(nav.angle_random_walk_rad_per_sqrt_s, 0.002 * kDeg / 60.0, 1e-15);
  EXPECT_NEAR(tac.gyro_bias_radps, 1.0 * kDeg / 3600.0, 1e-15);
  EXPECT_NEAR(tac.accel_bias_mps2, 1e-3 * 9.80665, 1e-12);
  EXPECT_NEAR(tac.velocity_random_walk_mps_per_sqrt_s, 0.06 / 60.0, 1e-15);
  // A tactical unit is worse than a navigation unit in every figure.
  EXPECT_GT(tac.accel_bias_mps2, nav.accel_bias_mps2);
  EXPECT_GT(tac.gyro_bias_radps, nav.gyro_bias_radps);
  EXPECT_GT(tac.accel_scale_factor, nav.accel_scale_factor);
  EXPECT_GT(tac.gyro_scale_factor, nav.gyro_scale_factor);
  EXPECT_GT(tac.velocity_random_walk_mps_per_sqrt_s, nav.velocity_random_walk_mps_per_sqrt_s);
  EXPECT_GT(tac.angle_random_walk_rad_per_sqrt_s, nav.angle_random_walk_rad_per_sqrt_s);
}

TEST(ImuErrorModel, SampledUnitsFollowTheSpecStatistics) {
  // Turn-on biases over many units: RMS equals the 1-sigma figure (3 axes x 2000 units).
  const ImuErrorSpec spec = ImuErrorSpec::tactical_grade();
  double sum_sq = 0.0;
  const int units_drawn = 2000;
  for (int seed = 0; seed < units_drawn; ++seed) {
    sum_sq += ImuErrors::sample(spec, static_cast<std::uint64_t>(seed)).gyro_bias_body_radps.squaredNorm();
  }
  EXPECT_NEAR(std::sqrt(sum_sq / (3.0 * units_drawn)) / spec.gyro_bias_radps, 1.0, 0.03);
}

// A stationary INS of a given unit for `duration_s`; returns its errors.
NavigationErrors stationary_run(const InsConfig& config, double duration_s, double step_s) {
  const NavigationState truth = test::stationary_state(48.0 * kDeg, 11.0 * kDeg, 500.0);
  InertialNavigationSystem ins(config, truth);
  const ImuSample imu = test::stationary_imu(truth);
  const int steps = static_cast<int>(std::lround(duration_s / step_s));
  for (int i = 0; i < steps; ++i) ins.step(imu, step_s, truth.position.alt_m);
  return ins.errors_against(truth);
}

TEST(ImuErrorModel, SameSeedSameOutputDifferentSeedDifferentRandomWalk) {
  InsConfig config;
  config.integration_rate_hz = 50.0;
  config.imu_errors = ImuErrors::sample(ImuErrorSpec::tactical_grade(), 42);
  config.noise_seed = 7;
  const NavigationErrors a = stationary_run(config, 120.0, 0.02);
  const NavigationErrors b = stationary_run(config, 120.0, 0.02);
  EXPECT_EQ(a.position_ned_m, b.position_ned_m);
  EXPECT_EQ(a.velocity_ned_mps, b.velocity_ned_mps);
  EXPECT_EQ(a.attitude_ned_rad, b.attitude_ned_rad);
  config.noise_seed = 8;
  const NavigationErrors c = stationary_run(config, 120.0, 0.02);
  EXPECT_GT((a.velocity_ned_mps - c.velocity_ned_mps).norm(), 1e-4);
  // And a different unit (turn-on errors from another seed) differs too.
  config.noise_seed = 7;
  config.imu_errors = ImuErrors::sample(ImuErrorSpec::tactical_grade(), 43);
  const NavigationErrors d = stationary_run(config, 120.0, 0.02);
  EXPECT_GT((a.position_ned_m - d.position_ned_m).norm(), 1e-2);
}

TEST(ImuErrorModel, VelocityRandomWalkGrowsAsSqrtTimeWhateverTheRate) {
  // Only VRW: the north velocity error after t is N(0, VRW^2 t) (Schuler feedback negligible:
  // w_s t = 0.07 rad). 300 seeded runs at each of two integration rates.
  const double vrw = 0.06 / 60.0;  // 0.06 m/s/sqrt(h)
  const double duration_s = 60.0;
  for (double rate_hz : {10.0, 50.0}) {
    double sum_sq = 0.0;
    const int runs = 300;
    for (int seed = 0; seed < runs; ++seed) {
      InsConfig config;
      config.integration_rate_hz = rate_hz;
      config.imu_errors.velocity_random_walk_mps_per_sqrt_s = vrw;
      config.noise_seed = static_cast<std::uint64_t>(seed) + 1000;
      const NavigationErrors e = stationary_run(config, duration_s, 1.0);
      sum_sq += e.velocity_ned_mps.x() * e.velocity_ned_mps.x() +
                e.velocity_ned_mps.y() * e.velocity_ned_mps.y();
    }
    const double rms = std::sqrt(sum_sq / (2.0 * runs));
    EXPECT_NEAR(rms / (vrw * std::sqrt(duration_s)), 1.0, 0.1) << rate_hz << " Hz";
  }
}

TEST(VerticalChannel, FreeChannelDivergesAsCoshAndTheBaroLoopHoldsIt) {
  // A 100 ug down accelerometer bias b: free, dh'' = (2 g / R) dh - b gives
  // dh = -(b R / 2g)(cosh(t sqrt(2g/R)) - 1) (T&W ch. 12); baro-damped, dh -> 0 and the loop's
  // bias estimate -> b.
  const NavigationState truth = test::stationary_state(0.0, 0.0, 0.0);
  const double bias_mps2 = 1e-4 * units::kStandardGravityMps2;
  InsConfig config;
  config.integration_rate_hz = 10.0;
  config.imu_errors.accel_bias_body_mps2 = {0.0, 0.0, bias_mps2};
  config.vertical_channel = VerticalChannel::kFree;
  const double g = Wgs84::gravity_ecef(Wgs84::ecef_from_geodetic(truth.position)).norm();
  const double radius_m = std::sqrt(Wgs84::meridian_radius_m(0.0) * Wgs84::prime_vertical_radius_m(0.0));
  const double k = std::sqrt(2.0 * g / radius_m);  // 1 / 570 s
  const ImuSample imu = test::stationary_imu(truth);

  InertialNavigationSystem free_ins(config, truth);
  for (int i = 0; i < 1800; ++i) free_ins.step(imu, 1.0);
  const double expected_m = -(bias_mps2 / (k * k)) * (std::cosh(k * 1800.0) - 1.0);  // -3.5 km
  const double height_error_m = -free_ins.errors_against(truth).position_ned_m.z();
  EXPECT_NEAR(height_error_m / expected_m, 1.0, 0.03) << height_error_m << " vs " << expected_m;
  EXPECT_FALSE(free_ins.solution().vertical_channel_aided);

  config.vertical_channel = VerticalChannel::kBaroDamped;
  config.baro_loop_time_constant_s = 60.0;
  InertialNavigationSystem damped(config, truth);
  for (int i = 0; i < 1800; ++i) damped.step(imu, 1.0, truth.position.alt_m);
  EXPECT_LT(std::abs(damped.errors_against(truth).position_ned_m.z()), 0.01);
  EXPECT_TRUE(damped.solution().vertical_channel_aided);
  EXPECT_NEAR(damped.solution().baro_accel_bias_estimate_down_mps2 / bias_mps2, 1.0, 0.01);
  // A step without a baro height coasts free.
  damped.step(imu, 1.0);
  EXPECT_FALSE(damped.solution().vertical_channel_aided);
}

TEST(InputChecks, BadInputsAreRejected) {
  const NavigationState truth = test::stationary_state(10.0 * kDeg, 0.0, 0.0);
  InertialNavigationSystem ins(InsConfig{}, truth);
  ImuSample imu = test::stationary_imu(truth);
  const double nan = std::numeric_limits<double>::quiet_NaN();
  EXPECT_THROW(ins.step(imu, 0.0), std::invalid_argument);
  EXPECT_THROW(ins.step(imu, -0.01), std::invalid_argument);
  EXPECT_THROW(ins.step(imu, nan), std::invalid_argument);
  EXPECT_THROW(ins.step(imu, 0.01, nan), std::invalid_argument);
  ImuSample bad = imu;
  bad.specific_force_body_mps2.x() = nan;
  EXPECT_THROW(ins.step(bad, 0.01), std::invalid_argument);
  bad = imu;
  bad.omega_body_radps.z() = std::numeric_limits<double>::infinity();
  EXPECT_THROW(ins.step(bad, 0.01), std::invalid_argument);
  bad = imu;
  bad.omega_body_radps.y() = 100.0;  // rad/s, degrees given by mistake
  EXPECT_THROW(ins.step(bad, 0.01), std::invalid_argument);

  InsConfig config;
  config.integration_rate_hz = 0.0;
  EXPECT_THROW(InertialNavigationSystem(config, truth), std::invalid_argument);
  config = InsConfig{};
  config.baro_loop_time_constant_s = nan;
  EXPECT_THROW(InertialNavigationSystem(config, truth), std::invalid_argument);
  config = InsConfig{};
  config.imu_errors.accel_scale_factor_body.x() = 0.5;
  EXPECT_THROW(InertialNavigationSystem(config, truth), std::invalid_argument);
  NavigationState polar = truth;
  polar.position.lat_rad = 89.9 * kDeg;
  EXPECT_THROW(InertialNavigationSystem(InsConfig{}, polar), std::invalid_argument);
  NavigationState unnormalised = truth;
  unnormalised.q_ned_from_body.coeffs() *= 2.0;
  EXPECT_THROW(InertialNavigationSystem(InsConfig{}, unnormalised), std::invalid_argument);
  EXPECT_THROW(imu_sample_at_cg({0.0, 0.0, -9.8e3}, 0.0, Eigen::Vector3d::Zero()),
               std::invalid_argument);
  EXPECT_THROW(ImuErrors::sample(ImuErrorSpec{-1.0}, 1), std::invalid_argument);
  // The flight model's force and mass give the specific force.
  const ImuSample cg = imu_sample_at_cg({100.0, 0.0, -9806.65}, 1000.0, {0.01, 0.0, 0.0});
  EXPECT_DOUBLE_EQ(cg.specific_force_body_mps2.z(), -9.80665);
  EXPECT_DOUBLE_EQ(cg.specific_force_body_mps2.x(), 0.1);
}

}  // namespace
}  // namespace fedsim::nav
