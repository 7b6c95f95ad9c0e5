// Dryden continuous turbulence per MIL-F-8785C: gust velocities and gust rotation rates from
// seeded white noise through exactly discretised shaping filters.
#include "flight/model/weather/turbulence.hpp"
#include "common/units/units.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>
#include <stdexcept>
#include <string>
#include <vector>

namespace fedsim::flight {

namespace {
constexpr double kLowestAirspeedMps = 1.0;  // Taylor's hypothesis needs motion; avoids L / 0
constexpr double kLowAltitudeTopFt = 1000.0;
constexpr double kHighAltitudeBottomFt = 2000.0;
constexpr double kHighAltitudeScaleFt = 1750.0;
constexpr double kLowestHeightFt = 10.0;
const double kSqrt3 = std::sqrt(3.0);

// MIL-F-8785C figure 7: sigma (ft/s) against altitude (ft) for each probability of
// exceedance curve (the digitisation JSBSim's FGWinds carries).
constexpr std::array<double, 12> kExceedanceAltitudeFt = {500.0,   1750.0,  3750.0,  7500.0,
                                                          15000.0, 25000.0, 35000.0, 45000.0,
                                                          55000.0, 65000.0, 75000.0, 80000.0};
constexpr std::array<std::array<double, 12>, 7> kExceedanceSigmaFps = {{
    {3.2, 2.2, 1.5, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0},           // 1e-1
    {4.2, 3.6, 3.3, 1.6, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0},           // 1e-2 light
    {6.6, 6.9, 7.4, 6.7, 4.6, 2.7, 0.4, 0.0, 0.0, 0.0, 0.0, 0.0},           // 2e-3
    {8.6, 9.6, 10.6, 10.1, 8.0, 6.6, 5.0, 4.2, 2.7, 0.0, 0.0, 0.0},         // 1e-3 moderate
    {11.8, 13.0, 16.0, 15.1, 11.6, 9.7, 8.1, 8.2, 7.9, 4.9, 3.2, 2.1},      // 1e-4
    {15.6, 17.6, 23.0, 23.6, 22.1, 20.0, 16.0, 15.1, 12.1, 7.9, 6.2, 5.1},  // 1e-5 severe
    {18.7, 21.5, 28.4, 30.2, 30.7, 31.0, 25.2, 23.1, 17.5, 10.7, 8.4, 7.2}  // 1e-6
}};

Table1D exceedance_table(int curve) {
  std::vector<double> altitude_m, sigma_mps;
  for (std::size_t i = 0; i < kExceedanceAltitudeFt.size(); ++i) {
    altitude_m.push_back(kExceedanceAltitudeFt[i] * units::kFtToM);
    sigma_mps.push_back(curve == 0 ? 0.0 : kExceedanceSigmaFps[curve - 1][i] * units::kFtToM);
  }
  return Table1D(altitude_m, sigma_mps);
}

// Exact discretisation of the unit double-pole filter x1' = -x1 + xi, x2' = -x2 + x1 over a
// normalised step delta = dt / tau: transition exp(-delta) [[1, 0], [delta, 1]] and the
// Cholesky factor of the noise covariance integral_0^delta e^{-2s} [[1, s], [s, s^2]] ds.
struct DoublePoleStep {
  double decay, l11, l21, l22;
};

DoublePoleStep double_pole_step(double delta) {
  double q11, q12, q22;
  if (delta < 1e-3) {  // series: the closed forms cancel catastrophically for tiny steps
    const double d2 = delta * delta, d3 = d2 * delta, d4 = d3 * delta;
    q11 = delta - d2 + 2.0 * d3 / 3.0;
    q12 = d2 / 2.0 - 2.0 * d3 / 3.0 + d4 / 2.0;
    q22 = d3 / 3.0 - d4 / 2.0 + 2.0 * d4 * delta / 5.0;
  } else {
    const double e2 = std::exp(-2.0 * delta);
    q11 = -std::expm1(-2.0 * delta) / 2.0;
    q12 = (-std::expm1(-2.0 * delta) - 2.0 * delta * e2) / 4.0;
    q22 = (-std::expm1(-2.0 * delta) - e2 * (2.0 * delta + 2.0 * delta * delta)) / 4.0;
  }
  const double l11 = std::sqrt(q11);
  const double l21 = q12 / l11;
  return {std::exp(-delta), l11, l21, std::sqrt(std::max(q22 - l21 * l21, 0.0))};
}

// One step of a unit-variance first-order Gauss-Markov process with time constant tau.
double first_order_step(double y, double dt_s, double tau_s, double noise) {
  const double a = std::exp(-dt_s / tau_s);
  return a * y + std::sqrt(-std::expm1(-2.0 * dt_s / tau_s)) * noise;  // sqrt(1 - a^2)
}

// Dryden v / w output of the double-pole states: variance 1 in the stationary state.
double double_pole_output(const double x[2]) { return kSqrt3 * x[0] + (1.0 - kSqrt3) * x[1]; }

double lerp(double a, double b, double f) { return a + (b - a) * f; }
}  // namespace

void Turbulence::Params::validate() const {
  auto fail = [](const std::string& field, const std::string& rule) {
    throw std::invalid_argument("turbulence: " + field + " " + rule);
  };
  if (!(w20_mps >= 0.0) || !std::isfinite(w20_mps)) fail("w20_mps", "must be finite and >= 0");
  if (exceedance_curve < 0 || exceedance_curve > 7) fail("exceedance_curve", "must be 0..7");
  if (!(wingspan_m > 0.0) || !std::isfinite(wingspan_m)) fail("wingspan_m", "must be positive");
}

Turbulence::Params Turbulence::Params::for_severity(Severity severity, double wingspan_m,
                                                    std::uint64_t seed) {
  Params p;
  p.wingspan_m = wingspan_m;
  p.seed = seed;
  switch (severity) {
    case Severity::kNone:
      break;
    case Severity::kLight:
      p.w20_mps = 15.0 * units::kKtToMps;
      p.exceedance_curve = 2;
      break;
    case Severity::kModerate:
      p.w20_mps = 30.0 * units::kKtToMps;
      p.exceedance_curve = 4;
      break;
    case Severity::kSevere:
      p.w20_mps = 45.0 * units::kKtToMps;
      p.exceedance_curve = 6;
      break;
  }
  return p;
}

Turbulence::Turbulence(Params params) : params_(params) {
  params_.validate();
  high_altitude_sigma_ = exceedance_table(params_.exceedance_curve);
  reset();
}

void Turbulence::reset() {
  rng_.seed(params_.seed);
  normal_.reset();
  // Stationary start: unit variance, and for the double-pole states the covariance
  // [[1/2, 1/4], [1/4, 1/4]] (Cholesky [[1/sqrt2, 0], [sqrt2/4, sqrt2/4]]).
  auto stationary_double_pole = [this](double x[2]) {
    const double n1 = normal_(rng_), n2 = normal_(rng_);
    x[0] = n1 / std::numbers::sqrt2;
    x[1] = std::numbers::sqrt2 / 4.0 * (n1 + n2);
  };
  y_u_ = normal_(rng_);
  stationary_double_pole(y_v_);
  stationary_double_pole(y_w_);
  y_p_ = normal_(rng_);
  lags_primed_ = false;
  outputs_ = Outputs{};
}

Turbulence::Scales Turbulence::scales(double height_agl_m) const {
  const double h_ft =
      std::max(std::isnan(height_agl_m) ? 0.0 : height_agl_m / units::kFtToM, kLowestHeightFt);
  const double sigma_w_low = 0.1 * params_.w20_mps;
  auto low = [&](double h) {
    const double k = 0.177 + 0.000823 * h;
    Scales s;
    s.length_u_m = s.length_v_m = h / std::pow(k, 1.2) * units::kFtToM;
    s.length_w_m = h * units::kFtToM;
    s.sigma_w_mps = sigma_w_low;
    s.sigma_u_mps = s.sigma_v_mps = sigma_w_low / std::pow(k, 0.4);
    return s;
  };
  auto high = [&](double h) {
    Scales s;
    s.length_u_m = s.length_v_m = s.length_w_m = kHighAltitudeScaleFt * units::kFtToM;
    s.sigma_u_mps = s.sigma_v_mps = s.sigma_w_mps = high_altitude_sigma_(h * units::kFtToM);
    return s;
  };
  if (h_ft <= kLowAltitudeTopFt) return low(h_ft);
  if (h_ft >= kHighAltitudeBottomFt) return high(h_ft);
  const Scales a = low(kLowAltitudeTopFt), b = high(kHighAltitudeBottomFt);
  const double f = (h_ft - kLowAltitudeTopFt) / (kHighAltitudeBottomFt - kLowAltitudeTopFt);
  Scales s;
  s.length_u_m = lerp(a.length_u_m, b.length_u_m, f);
  s.length_v_m = lerp(a.length_v_m, b.length_v_m, f);
  s.length_w_m = lerp(a.length_w_m, b.length_w_m, f);
  s.sigma_u_mps = lerp(a.sigma_u_mps, b.sigma_u_mps, f);
  s.sigma_v_mps = lerp(a.sigma_v_mps, b.sigma_v_mps, f);
  s.sigma_w_mps = lerp(a.sigma_w_mps, b.sigma_w_mps, f);
  return s;
}

double Turbulence::roll_rate_sigma_radps(double sigma_w_mps, double length_w_m) const {
  // Variance = integral_0^inf |H_p(j omega)|^2 d omega = G^2 pi / (2 tau_p), tau_p = 4b/(pi V);
  // the airspeed cancels.
  const double b = params_.wingspan_m;
  return sigma_w_mps * std::sqrt(0.1 / b) * std::numbers::pi *
         std::pow(std::numbers::pi / (4.0 * b), 1.0 / 6.0) / std::cbrt(length_w_m);
}

Turbulence::FilterSample Turbulence::advance_filters(double dt_s, double tas_mps, const Scales& s) {
  y_u_ = first_order_step(y_u_, dt_s, s.length_u_m / tas_mps, normal_(rng_));
  auto advance_double_pole = [&](double x[2], double tau_s) {
    const double delta = dt_s / tau_s;
    const DoublePoleStep k = double_pole_step(delta);
    const double n1 = normal_(rng_), n2 = normal_(rng_);
    const double x1 = k.decay * x[0] + k.l11 * n1;
    const double x2 = k.decay * (delta * x[0] + x[1]) + k.l21 * n1 + k.l22 * n2;
    x[0] = x1;
    x[1] = x2;
  };
  advance_double_pole(y_v_, s.length_v_m / tas_mps);
  advance_double_pole(y_w_, s.length_w_m / tas_mps);
  return {y_u_, double_pole_output(y_v_), double_pole_output(y_w_)};
}

Eigen::Vector3d Turbulence::to_ned(const Eigen::Vector3d& uvw, const Inputs& in) const {
  const double h_ft = std::isnan(in.height_agl_m) ? 0.0 : in.height_agl_m / units::kFtToM;
  const double f = std::clamp(
      (h_ft - kLowAltitudeTopFt) / (kHighAltitudeBottomFt - kLowAltitudeTopFt), 0.0, 1.0);
  const Eigen::Matrix3d ned_from_body = in.body_from_ned.transpose();
  const Eigen::Vector3d high = ned_from_body * uvw;
  if (f >= 1.0) return high;
  // Low altitude: u along the mean wind, v to its right, w down. Calm air: along the
  // aircraft's horizontal heading.
  Eigen::Vector2d along = in.mean_wind_ned_mps.head<2>();
  if (!(along.norm() > 0.1)) along = ned_from_body.col(0).head<2>();
  along = along.norm() > 1e-9 ? Eigen::Vector2d(along.normalized()) : Eigen::Vector2d::UnitX();
  const Eigen::Vector3d low(uvw.x() * along.x() - uvw.y() * along.y(),
                            uvw.x() * along.y() + uvw.y() * along.x(), uvw.z());
  return low + f * (high - low);
}

void Turbulence::step(double dt_s, const Inputs& in) {
  if (!(dt_s > 0.0)) return;
  const double v = std::max(std::isnan(in.tas_mps) ? 0.0 : in.tas_mps, kLowestAirspeedMps);
  const Scales s = scales(in.height_agl_m);
  const FilterSample unit = advance_filters(dt_s, v, s);
  const Eigen::Vector3d uvw(s.sigma_u_mps * unit.u, s.sigma_v_mps * unit.v, s.sigma_w_mps * unit.w);

  Outputs& out = outputs_;
  out.scales = s;
  out.gust_ned_mps = to_ned(uvw, in);
  out.gust_body_mps = in.body_from_ned * out.gust_ned_mps;

  // Gust rates: p_g its own first-order process; q_g and r_g from the body-axis w and v
  // gusts through s / (1 + tau s) = (1 - low-pass) / tau.
  const double b = params_.wingspan_m;
  const double tau_p = 4.0 * b / (std::numbers::pi * v);
  const double tau_q = 4.0 * b / (std::numbers::pi * v);
  const double tau_r = 3.0 * b / (std::numbers::pi * v);
  y_p_ = first_order_step(y_p_, dt_s, tau_p, normal_(rng_));
  const double w_body = out.gust_body_mps.z(), v_body = out.gust_body_mps.y();
  if (!lags_primed_) {
    lag_w_mps_ = w_body;
    lag_v_mps_ = v_body;
    lags_primed_ = true;
  }
  lag_w_mps_ += (w_body - lag_w_mps_) * -std::expm1(-dt_s / tau_q);
  lag_v_mps_ += (v_body - lag_v_mps_) * -std::expm1(-dt_s / tau_r);
  out.gust_rates_body_radps =
      Eigen::Vector3d(roll_rate_sigma_radps(s.sigma_w_mps, s.length_w_m) * y_p_,
                      -(w_body - lag_w_mps_) / (v * tau_q), (v_body - lag_v_mps_) / (v * tau_r));
}

}  // namespace fedsim::flight
