// Free-inertial error propagation of a stationary INS against the analytic single-channel
// error model (Titterton & Weston 2nd ed. ch. 12): the Schuler oscillation of period
// 2 pi sqrt(R/g) ~ 84.4 min, the response to an initial velocity error (amplitude dv0/w_s), an
// accelerometer bias (b/w_s^2), a tilt (R phi) and a gyro bias (position error growing as
// R eps (t - sin(w_s t)/w_s)).
// Coarse steps (1 s at 1 Hz) keep several hours of simulated time well under a second; the
// vertical channel is baro-damped with the true height so that it cannot diverge.
#include "federates/nav/model/ins/inertial_navigation_system.hpp"
#include "federates/nav/model/ins/test/ins_test_support.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <vector>

namespace fedsim::nav {
namespace {

using test::kDeg;

struct ErrorHistory {
  std::vector<double> time_s;
  std::vector<double> north_m;
  std::vector<double> east_m;
  std::vector<double> horizontal_m;
  std::vector<double> down_m;
};

// Runs a stationary INS for `duration_s` in 1 s steps and records its position errors.
ErrorHistory run_stationary(const NavigationState& truth, const InsConfig& config,
                            const InitialErrors& initial, double duration_s,
                            double step_s = 1.0) {
  InertialNavigationSystem ins(config, truth, initial);
  const ImuSample imu = test::stationary_imu(truth);
  ErrorHistory history;
  const int steps = static_cast<int>(std::lround(duration_s / step_s));
  for (int i = 0; i < steps; ++i) {
    ins.step(imu, step_s, truth.position.alt_m);
    const NavigationErrors e = ins.errors_against(truth);
    history.time_s.push_back(ins.time_s());
    history.north_m.push_back(e.position_ned_m.x());
    history.east_m.push_back(e.position_ned_m.y());
    history.horizontal_m.push_back(e.horizontal_position_m);
    history.down_m.push_back(e.position_ned_m.z());
  }
  return history;
}

InsConfig coarse_config() {
  InsConfig config;
  config.integration_rate_hz = 1.0;
  config.vertical_channel = VerticalChannel::kBaroDamped;
  return config;
}

// The Schuler frequency of the east channel, w_s^2 = g / (R_E + h), at a position.
double east_schuler_rate_radps(const NavigationState& s) {
  const double g = Wgs84::gravity_ecef(Wgs84::ecef_from_geodetic(s.position)).norm();
  return std::sqrt(g / (Wgs84::prime_vertical_radius_m(s.position.lat_rad) + s.position.alt_m));
}

double value_at(const ErrorHistory& h, const std::vector<double>& series, double t_s) {
  const auto it = std::lower_bound(h.time_s.begin(), h.time_s.end(), t_s - 1e-9);
  return series[static_cast<std::size_t>(it - h.time_s.begin())];
}

constexpr double kSchulerPeriodS = 84.4 * 60.0;  // 2 pi sqrt(R/g), R 6371 km, g 9.81 m/s^2

// At the equator, heading north, the east channel (tilt about north, east accelerometer, north
// gyro) is the single-axis Schuler loop of the textbooks: dv_E' = g phi_N + b_E,
// phi_N' = eps_N - dv_E / (R_E + h) (with C_ins = (I + [phi x]) C_truth), and the earth rate
// (along north there) couples neither phi_N nor dv_E into the other channels' horizontal errors.
// The north channel is not so clean: the earth rate turns a tilt about east into a heading
// error (gyrocompass coupling, ~7 % after one period), so it is not used for amplitudes.
NavigationState equator_heading_north() { return test::stationary_state(0.0, 0.0, 0.0); }

TEST(Schuler, InitialVelocityErrorOscillatesWithTheSchulerPeriod) {
  // 0.1 m/s north velocity error at 45 deg N: dN = dv0 sin(w_s t) / w_s cos(Omega sin L t)
  // (Foucault-modulated); the horizontal magnitude |dv0 sin(w_s t) / w_s| is free of it.
  const NavigationState truth = test::stationary_state(45.0 * kDeg, 10.0 * kDeg, 100.0);
  InitialErrors initial;
  initial.velocity_ned_mps = {0.1, 0.0, 0.0};
  const ErrorHistory h = run_stationary(truth, coarse_config(), initial, 4.2 * kSchulerPeriodS);

  const std::vector<double> crossings = test::zero_crossings(h.time_s, h.north_m);
  ASSERT_GE(crossings.size(), 8u);
  const double period_s = test::period_from_crossings(crossings);
  EXPECT_NEAR(period_s / kSchulerPeriodS, 1.0, 0.01) << "period " << period_s / 60.0 << " min";
  // Crossings every half period from t = T/2 on.
  EXPECT_NEAR(crossings.front() / (0.5 * kSchulerPeriodS), 1.0, 0.01);
  // Amplitude dv0 / w_s = 0.1 m/s * 806 s = 80.6 m at the odd quarter periods.
  const double ws = 2.0 * units::kPi / period_s;
  for (double k : {1.0, 3.0, 5.0, 7.0}) {
    EXPECT_NEAR(value_at(h, h.horizontal_m, k * 0.25 * period_s) / (0.1 / ws), 1.0, 0.01)
        << "quarter period " << k;
  }
}

TEST(Schuler, EquatorialPeriodMatchesTheLocalRadiusOfCurvature) {
  // East channel at the equator: period 2 pi sqrt((R_E + h) / g) with R_E = a = 6378.137 km.
  InitialErrors initial;
  initial.velocity_ned_mps = {0.0, 0.1, 0.0};
  const NavigationState truth = equator_heading_north();
  const ErrorHistory h = run_stationary(truth, coarse_config(), initial, 5.2 * kSchulerPeriodS);
  const double period_s = test::period_from_crossings(test::zero_crossings(h.time_s, h.east_m));
  const double expected_s = 2.0 * units::kPi / east_schuler_rate_radps(truth);
  EXPECT_NEAR(period_s / expected_s, 1.0, 0.001) << period_s << " vs " << expected_s;
  EXPECT_NEAR(period_s / kSchulerPeriodS, 1.0, 0.01);
}

TEST(Schuler, InitialPositionErrorAloneDoesNotExciteTheSchulerLoop) {
  // An INS aligned level (to the truth's attitude) but dN0 = 100 m north is a consistent INS at
  // the wrong place: no tilt, no velocity error, so no Schuler swing (a tilt of dN0/R = 16 urad
  // would swing it by 2 R phi = 200 m). What moves it is the earth rate it computes at the wrong
  // latitude: the gyros sense Omega at L, the INS removes it at L + dL, an apparent north gyro
  // bias Omega sin L dL that drifts it east at R Omega sin L dL = dN0 Omega sin L (24-hour
  // effect; 5.2 mm/s, 26 m after one Schuler period at 45 deg).
  const NavigationState truth = test::stationary_state(45.0 * kDeg, 10.0 * kDeg, 100.0);
  InitialErrors initial;
  initial.position_ned_m = {100.0, 0.0, 0.0};
  const ErrorHistory h = run_stationary(truth, coarse_config(), initial, kSchulerPeriodS);
  for (double n : h.north_m) EXPECT_NEAR(n, 100.0, 10.0);
  const double east_drift_m = 100.0 * wgs84::kEarthRateRadps * std::sin(truth.position.lat_rad) *
                              h.time_s.back();
  EXPECT_NEAR(h.east_m.back() / east_drift_m, 1.0, 0.05) << h.east_m.back() << " vs " << east_drift_m;
}

TEST(Schuler, AccelerometerBiasGivesPositionErrorOfAmplitudeBiasOverSchulerRateSquared) {
  // b along east: dE = (b / w_s^2)(1 - cos w_s t): mean b/w_s^2, peak 2 b/w_s^2 at T/2.
  const NavigationState truth = equator_heading_north();
  InsConfig config = coarse_config();
  const double bias_mps2 = 1e-4 * units::kStandardGravityMps2;  // 100 ug
  config.imu_errors.accel_bias_body_mps2 = {0.0, bias_mps2, 0.0};
  const double ws = east_schuler_rate_radps(truth);
  const double period_s = 2.0 * units::kPi / ws;
  const ErrorHistory h = run_stationary(truth, config, {}, 3.0 * period_s);

  const double amplitude_m = bias_mps2 / (ws * ws);  // b R / g = 638 m
  const double peak_m = *std::max_element(h.east_m.begin(), h.east_m.end());
  EXPECT_NEAR(peak_m / (2.0 * amplitude_m), 1.0, 0.01) << "peak " << peak_m;
  for (double k : {0.5, 1.5, 2.5}) {
    EXPECT_NEAR(value_at(h, h.east_m, k * period_s) / (2.0 * amplitude_m), 1.0, 0.01) << k;
  }
  for (double k : {1.0, 2.0, 3.0}) {
    EXPECT_NEAR(value_at(h, h.east_m, k * period_s), 0.0, 0.01 * amplitude_m) << k;
  }
  // Period of the oscillation about the mean b / w_s^2.
  std::vector<double> about_mean(h.east_m.size());
  std::transform(h.east_m.begin(), h.east_m.end(), about_mean.begin(),
                 [&](double e) { return e - amplitude_m; });
  const double measured_period_s =
      test::period_from_crossings(test::zero_crossings(h.time_s, about_mean));
  EXPECT_NEAR(measured_period_s / period_s, 1.0, 0.01);
  EXPECT_NEAR(measured_period_s / kSchulerPeriodS, 1.0, 0.01);
  // The north channel is not driven.
  for (double n : h.north_m) EXPECT_LT(std::abs(n), 0.01 * amplitude_m);
}

TEST(Schuler, TiltErrorGivesTheAnalyticOscillation) {
  // 0.1 mrad about north: dv_E' = g phi_N, so dE = R phi_N (1 - cos w_s t): 1276 m at T/2.
  const NavigationState truth = equator_heading_north();
  InitialErrors initial;
  const double tilt_rad = 1e-4;
  initial.tilt_ned_rad = {tilt_rad, 0.0, 0.0};
  const double ws = east_schuler_rate_radps(truth);
  const double period_s = 2.0 * units::kPi / ws;
  const ErrorHistory h = run_stationary(truth, coarse_config(), initial, 3.0 * period_s);
  const double g = Wgs84::gravity_ecef(Wgs84::ecef_from_geodetic(truth.position)).norm();
  const double amplitude_m = g * tilt_rad / (ws * ws);
  for (double k : {0.5, 1.5, 2.5}) {
    EXPECT_NEAR(value_at(h, h.east_m, k * period_s) / (2.0 * amplitude_m), 1.0, 0.01) << k;
  }
  for (double k : {1.0, 2.0}) {
    EXPECT_NEAR(value_at(h, h.east_m, k * period_s), 0.0, 0.01 * amplitude_m) << k;
  }
}

TEST(Schuler, GyroBiasGivesLinearlyGrowingPositionError) {
  // eps about north: dv_E = R eps (1 - cos w_s t), dE = R eps (t - sin(w_s t) / w_s): a mean
  // drift of R eps (0.31 m/s = 0.6 nmi/h for 0.01 deg/h) with the Schuler ripple on top.
  const NavigationState truth = equator_heading_north();
  InsConfig config = coarse_config();
  const double eps_radps = 0.01 * kDeg / 3600.0;
  config.imu_errors.gyro_bias_body_radps = {eps_radps, 0.0, 0.0};
  const double ws = east_schuler_rate_radps(truth);
  const double period_s = 2.0 * units::kPi / ws;
  const double radius_m = Wgs84::prime_vertical_radius_m(0.0);
  const ErrorHistory h = run_stationary(truth, config, {}, 2.0 * period_s + 10.0);
  for (double fraction : {0.25, 0.5, 0.75, 1.0, 1.5, 2.0}) {
    const double t = fraction * period_s;
    const double expected_m = radius_m * eps_radps * (t - std::sin(ws * t) / ws);
    EXPECT_NEAR(value_at(h, h.east_m, t) / expected_m, 1.0, 0.01)
        << "at " << fraction << " T: " << value_at(h, h.east_m, t) << " vs " << expected_m;
  }
}

TEST(Schuler, PerfectStationaryInsStaysPutAndABiasMovesIt) {
  // Negative control for the tests above: no errors, no motion (free vertical channel too).
  const NavigationState truth = test::stationary_state(52.0 * kDeg, -1.0 * kDeg, 50.0, 30.0 * kDeg);
  InsConfig config = coarse_config();
  config.vertical_channel = VerticalChannel::kFree;
  const ErrorHistory perfect = run_stationary(truth, config, {}, 7200.0);
  const double worst_m = *std::max_element(perfect.horizontal_m.begin(), perfect.horizontal_m.end());
  EXPECT_LT(worst_m, 1e-3);
  EXPECT_LT(std::abs(perfect.down_m.back()), 1e-3);

  config.imu_errors.accel_bias_body_mps2 = {1e-5, 0.0, 0.0};  // 1 ug
  const ErrorHistory biased = run_stationary(truth, config, {}, 7200.0);
  EXPECT_GT(*std::max_element(biased.horizontal_m.begin(), biased.horizontal_m.end()), 5.0);
}

}  // namespace
}  // namespace fedsim::nav
