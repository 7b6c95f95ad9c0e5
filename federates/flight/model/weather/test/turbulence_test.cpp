// Tests of the Dryden turbulence: MIL-F-8785C scale lengths and intensities, seed
// determinism, and the variance and autocorrelation of long runs against the Dryden forms.
#include "flight/model/weather/turbulence.hpp"
#include "common/units/units.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <stdexcept>
#include <string>
#include <vector>

namespace fedsim::flight {
namespace {

constexpr double kFt = units::kFtToM;
constexpr double kKnot = units::kKtToMps;

// Sample statistics of a zero-mean series.
double variance(const std::vector<double>& x) {
  double sum = 0.0, sum2 = 0.0;
  for (double v : x) {
    sum += v;
    sum2 += v * v;
  }
  const double n = static_cast<double>(x.size());
  return sum2 / n - (sum / n) * (sum / n);
}

double autocorrelation(const std::vector<double>& x, std::size_t lag) {
  double mean = 0.0;
  for (double v : x) mean += v;
  mean /= static_cast<double>(x.size());
  double c = 0.0;
  for (std::size_t i = 0; i + lag < x.size(); ++i) c += (x[i] - mean) * (x[i + lag] - mean);
  return c / static_cast<double>(x.size() - lag) / variance(x);
}

struct GustSeries {
  std::vector<double> u, v, w, p, q;  // components in the turbulence axes / body rates
};

// Level flight heading north at constant height and airspeed, body axes = NED.
GustSeries fly(Turbulence& turb, double tas_mps, double height_m, double dt_s, std::size_t steps,
               const Eigen::Vector3d& mean_wind = Eigen::Vector3d::Zero()) {
  Turbulence::Inputs in;
  in.tas_mps = tas_mps;
  in.height_agl_m = height_m;
  in.mean_wind_ned_mps = mean_wind;
  GustSeries run;
  for (std::size_t i = 0; i < steps; ++i) {
    turb.step(dt_s, in);
    const Turbulence::Outputs& out = turb.outputs();
    run.u.push_back(out.gust_ned_mps.x());
    run.v.push_back(out.gust_ned_mps.y());
    run.w.push_back(out.gust_ned_mps.z());
    run.p.push_back(out.gust_rates_body_radps.x());
    run.q.push_back(out.gust_rates_body_radps.y());
  }
  return run;
}

TEST(Turbulence, LowAltitudeScalesFollowMilF8785C) {
  Turbulence::Params p;
  p.w20_mps = 30.0 * kKnot;  // moderate
  const Turbulence turb(p);
  const double h = 100.0;  // ft
  const Turbulence::Scales s = turb.scales(h * kFt);
  const double k = 0.177 + 0.000823 * h;
  EXPECT_NEAR(s.length_w_m, 100.0 * kFt, 1e-9);
  EXPECT_NEAR(s.length_u_m, h / std::pow(k, 1.2) * kFt, 1e-9);  // 505 ft
  EXPECT_NEAR(s.length_u_m / kFt, 505.1, 0.1);
  EXPECT_NEAR(s.sigma_w_mps, 3.0 * kKnot, 1e-12);                             // 0.1 W20
  EXPECT_NEAR(s.sigma_u_mps / s.sigma_w_mps, 1.0 / std::pow(k, 0.4), 1e-12);  // 1.716
  EXPECT_NEAR(s.sigma_v_mps, s.sigma_u_mps, 1e-12);
  // At 1000 ft the low-altitude model is isotropic with L = 1000 ft.
  const Turbulence::Scales top = turb.scales(1000.0 * kFt);
  EXPECT_NEAR(top.length_u_m, 1000.0 * kFt, 1e-9);
  EXPECT_NEAR(top.length_w_m, 1000.0 * kFt, 1e-9);
  EXPECT_NEAR(top.sigma_u_mps, top.sigma_w_mps, 1e-12);
  // Heights below 10 ft use 10 ft.
  EXPECT_NEAR(turb.scales(0.0).length_w_m, 10.0 * kFt, 1e-12);
}

TEST(Turbulence, HighAltitudeIntensityFromTheExceedanceCurves) {
  const Turbulence turb(Turbulence::Params::for_severity(Turbulence::Severity::kModerate, 30.0, 1));
  // 1e-3 curve: 10.1 ft/s at 7500 ft, 8.0 at 15000 ft -> 9.4 ft/s at 10000 ft.
  const Turbulence::Scales s = turb.scales(10000.0 * kFt);
  EXPECT_NEAR(s.sigma_w_mps / kFt, 9.4, 1e-9);
  EXPECT_NEAR(s.sigma_u_mps, s.sigma_w_mps, 1e-12);
  EXPECT_NEAR(s.length_u_m, 1750.0 * kFt, 1e-9);
  EXPECT_NEAR(s.length_w_m, 1750.0 * kFt, 1e-9);
  // Severe (1e-5) at 25000 ft: 20 ft/s.
  const Turbulence severe(Turbulence::Params::for_severity(Turbulence::Severity::kSevere, 30.0, 1));
  EXPECT_NEAR(severe.scales(25000.0 * kFt).sigma_w_mps / kFt, 20.0, 1e-9);
  EXPECT_NEAR(severe.params().w20_mps, 45.0 * kKnot, 1e-12);
  // Between 1000 and 2000 ft: half way at 1500 ft.
  const Turbulence::Scales mid = turb.scales(1500.0 * kFt);
  const double sigma_2000 = (9.6 + (10.6 - 9.6) * 250.0 / 2000.0) * kFt;  // curve at 2000 ft
  EXPECT_NEAR(mid.sigma_w_mps, 0.5 * (3.0 * kKnot + sigma_2000), 1e-9);
  EXPECT_NEAR(mid.length_w_m, 0.5 * (1000.0 + 1750.0) * kFt, 1e-9);
}

TEST(Turbulence, SameSeedSameGustsOtherSeedOtherGusts) {
  auto params = [](std::uint64_t seed) {
    return Turbulence::Params::for_severity(Turbulence::Severity::kModerate, 11.0, seed);
  };
  Turbulence a(params(42)), b(params(42)), c(params(43));
  const GustSeries ra = fly(a, 60.0, 300.0, 0.02, 2000);
  const GustSeries rb = fly(b, 60.0, 300.0, 0.02, 2000);
  const GustSeries rc = fly(c, 60.0, 300.0, 0.02, 2000);
  EXPECT_EQ(ra.u, rb.u);
  EXPECT_EQ(ra.w, rb.w);
  EXPECT_EQ(ra.p, rb.p);
  EXPECT_NE(ra.u, rc.u);
  EXPECT_NE(ra.w, rc.w);
  // reset() replays the sequence.
  a.reset();
  EXPECT_EQ(fly(a, 60.0, 300.0, 0.02, 2000).v, ra.v);
}

TEST(Turbulence, VarianceAndAutocorrelationMatchDryden) {
  // Medium altitude, severe: sigma 23.5 ft/s, L = 1750 ft (533 m); V = 200 m/s, tau = 2.67 s.
  Turbulence turb(Turbulence::Params::for_severity(Turbulence::Severity::kSevere, 30.0, 7));
  const double height = 3000.0, tas = 200.0;
  const Turbulence::Scales s = turb.scales(height);
  const double tau = s.length_w_m / tas;
  const std::size_t per_tau = 20;
  const double dt = tau / per_tau;
  const GustSeries run = fly(turb, tas, height, dt, 8000 * per_tau);  // 8000 tau = 21 000 s
  // Variance within 5 % (about three standard errors of the estimate).
  EXPECT_NEAR(variance(run.u) / (s.sigma_u_mps * s.sigma_u_mps), 1.0, 0.05);
  EXPECT_NEAR(variance(run.v) / (s.sigma_v_mps * s.sigma_v_mps), 1.0, 0.05);
  EXPECT_NEAR(variance(run.w) / (s.sigma_w_mps * s.sigma_w_mps), 1.0, 0.05);
  // R_u(xi) = exp(-xi/L); R_w(xi) = (1 - xi/2L) exp(-xi/L): at lag L/V and 2L/V.
  EXPECT_NEAR(autocorrelation(run.u, per_tau), std::exp(-1.0), 0.03);
  EXPECT_NEAR(autocorrelation(run.u, 2 * per_tau), std::exp(-2.0), 0.03);
  EXPECT_NEAR(autocorrelation(run.w, per_tau), 0.5 * std::exp(-1.0), 0.03);
  EXPECT_NEAR(autocorrelation(run.v, per_tau), 0.5 * std::exp(-1.0), 0.03);
  EXPECT_NEAR(autocorrelation(run.w, 2 * per_tau), 0.0, 0.03);
  EXPECT_NEAR(autocorrelation(run.w, per_tau / 2), 0.75 * std::exp(-0.5), 0.03);
  // Roll gust rate: variance of the MIL-F-8785C H_p filter.
  const double sigma_p = turb.roll_rate_sigma_radps(s.sigma_w_mps, s.length_w_m);
  EXPECT_NEAR(variance(run.p) / (sigma_p * sigma_p), 1.0, 0.05);
}

TEST(Turbulence, StatisticsDoNotDependOnTheStepSize) {
  // Exact discretisation: a coarse 0.5 s step gives the same variance and correlation.
  Turbulence turb(Turbulence::Params::for_severity(Turbulence::Severity::kModerate, 30.0, 3));
  const double height = 5000.0, tas = 100.0;
  const Turbulence::Scales s = turb.scales(height);
  const double tau = s.length_w_m / tas;  // 5.3 s
  const GustSeries run = fly(turb, tas, height, tau / 10.0, 200000);
  EXPECT_NEAR(variance(run.w) / (s.sigma_w_mps * s.sigma_w_mps), 1.0, 0.05);
  EXPECT_NEAR(autocorrelation(run.w, 10), 0.5 * std::exp(-1.0), 0.03);
}

TEST(Turbulence, LowAltitudeAxesFollowTheMeanWind) {
  // W20 = 30 kt at 200 ft; mean wind from the west (blowing east): u_g (first-order
  // spectrum) lies along east, v_g (second-order) along south-north.
  Turbulence::Params p;
  p.w20_mps = 30.0 * kKnot;
  p.wingspan_m = 11.0;
  p.seed = 11;
  Turbulence turb(p);
  const double height = 200.0 * kFt;
  const Turbulence::Scales s = turb.scales(height);
  const double tas = 50.0, tau = s.length_u_m / tas;
  const GustSeries run =
      fly(turb, tas, height, tau / 10.0, 200000, Eigen::Vector3d(0.0, 12.0, 0.0));
  EXPECT_NEAR(autocorrelation(run.v, 20), std::exp(-2.0), 0.03);  // east: u_g
  EXPECT_NEAR(autocorrelation(run.u, 20), 0.0, 0.03);             // north: v_g
  EXPECT_NEAR(variance(run.v) / (s.sigma_u_mps * s.sigma_u_mps), 1.0, 0.05);
  EXPECT_NEAR(variance(run.w) / (s.sigma_w_mps * s.sigma_w_mps), 1.0, 0.05);
}

TEST(Turbulence, PitchGustRateIsMinusTheSlopeOfTheVerticalGust) {
  // q_g = -dw_g/dx = -(1/V) dw_g/dt once the 4b/(pi V) lag has passed; with a small span
  // the lag is short and the two series nearly coincide.
  Turbulence::Params p = Turbulence::Params::for_severity(Turbulence::Severity::kModerate, 2.0, 5);
  Turbulence turb(p);
  const double tas = 50.0, dt = 0.005;
  const GustSeries run = fly(turb, tas, 3000.0, dt, 100000);
  double num = 0.0, den_q = 0.0, den_s = 0.0;
  for (std::size_t i = 1; i < run.w.size(); ++i) {
    const double slope = -(run.w[i] - run.w[i - 1]) / (tas * dt);
    num += slope * run.q[i];
    den_q += run.q[i] * run.q[i];
    den_s += slope * slope;
  }
  EXPECT_GT(num / std::sqrt(den_q * den_s), 0.3);  // positively correlated, same sign
}

TEST(Turbulence, NoTurbulenceGivesZeroAndStandstillIsFinite) {
  Turbulence calm(Turbulence::Params{});
  const GustSeries run = fly(calm, 60.0, 1000.0, 0.02, 100);
  for (double x : run.u) EXPECT_EQ(x, 0.0);
  Turbulence turb(Turbulence::Params::for_severity(Turbulence::Severity::kSevere, 30.0, 9));
  Turbulence::Inputs in;  // parked: zero airspeed and height
  for (int i = 0; i < 1000; ++i) {
    turb.step(0.02, in);
    ASSERT_TRUE(turb.outputs().gust_ned_mps.allFinite());
    ASSERT_TRUE(turb.outputs().gust_rates_body_radps.allFinite());
  }
  in.tas_mps = std::nan("");
  in.height_agl_m = std::nan("");
  turb.step(0.02, in);
  EXPECT_TRUE(turb.outputs().gust_body_mps.allFinite());
}

TEST(Turbulence, ValidateNamesTheBadField) {
  Turbulence::Params p;
  p.exceedance_curve = 8;
  try {
    p.validate();
    FAIL() << "no exception";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("exceedance_curve"), std::string::npos);
  }
  p = Turbulence::Params{};
  p.wingspan_m = 0.0;
  EXPECT_THROW(Turbulence{p}, std::invalid_argument);
}

}  // namespace
}  // namespace fedsim::flight
