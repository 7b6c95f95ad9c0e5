#include "visual/model/eye_extrapolation.hpp"

#include "common/units/units.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

namespace fedsim::visual {
namespace {

using units::kPi;
// WGS-84 (NIMA TR8350.2): semi-major axis and first eccentricity squared.
constexpr double kWgs84A = 6378137.0;
constexpr double kWgs84E2 = 6.69437999014e-3;

void check_finite3(const std::array<double, 3>& v, const char* field, std::string_view where) {
  for (double x : v) {
    if (!std::isfinite(x)) {
      throw std::invalid_argument(std::string(where) + ": field '" + field + "': not a finite number");
    }
  }
}

double wrap_pi(double angle_rad) {
  angle_rad = std::fmod(angle_rad + kPi, 2.0 * kPi);
  if (angle_rad < 0.0) angle_rad += 2.0 * kPi;
  return angle_rad - kPi;
}

}  // namespace

EyePose extrapolate(const MovingPose& state, double span_s, std::string_view where) {
  validate(state.pose, where);
  check_finite3(state.velocity_ned_mps, "velocity_ned_mps", where);
  check_finite3(state.omega_body_radps, "omega_body_radps", where);
  if (!std::isfinite(span_s)) {
    throw std::invalid_argument(std::string(where) + ": extrapolation span: not a finite number");
  }
  const double dt = std::clamp(span_s, 0.0, kMaxExtrapolationS);
  const EyePose& p = state.pose;
  EyePose out = p;
  // Radii of curvature: meridian M and prime vertical N (geodetic latitude rates).
  const double s = std::sin(p.lat_rad);
  const double w = std::sqrt(1.0 - kWgs84E2 * s * s);
  const double n = kWgs84A / w;
  const double m = kWgs84A * (1.0 - kWgs84E2) / (w * w * w);
  const double cos_lat = std::max(std::cos(p.lat_rad), 1e-6);
  out.lat_rad = p.lat_rad + state.velocity_ned_mps[0] * dt / (m + p.alt_msl_m);
  out.lon_rad = wrap_pi(p.lon_rad + state.velocity_ned_mps[1] * dt / ((n + p.alt_msl_m) * cos_lat));
  out.alt_msl_m = p.alt_msl_m - state.velocity_ned_mps[2] * dt;
  // Euler rates (seed eq. 3.48); cos(theta) kept off zero (the pose check bounds theta at 90 deg).
  const double pr = state.omega_body_radps[0], qr = state.omega_body_radps[1], rr = state.omega_body_radps[2];
  const double sphi = std::sin(p.phi_rad), cphi = std::cos(p.phi_rad);
  const double cos_theta = std::cos(p.theta_rad);
  const double safe_cos_theta = std::copysign(std::max(std::fabs(cos_theta), 1e-3), cos_theta);
  const double phi_dot = pr + (qr * sphi + rr * cphi) * std::tan(p.theta_rad);
  const double theta_dot = qr * cphi - rr * sphi;
  const double psi_dot = (qr * sphi + rr * cphi) / safe_cos_theta;
  out.phi_rad = wrap_pi(p.phi_rad + phi_dot * dt);
  out.theta_rad = std::clamp(p.theta_rad + theta_dot * dt, -kPi / 2, kPi / 2);
  out.psi_rad = wrap_pi(p.psi_rad + psi_dot * dt);
  return out;
}

}  // namespace fedsim::visual
