// Navigation state checks, errors against the truth and initial perturbations.
#include "federates/nav/model/ins/navigation_state.hpp"

#include "common/units/units.hpp"

#include <cmath>
#include <stdexcept>
#include <string>

namespace fedsim::nav {

namespace {

[[noreturn]] void fail(std::string_view origin, const std::string& what) {
  throw std::invalid_argument(std::string(origin) + ": " + what);
}

Eigen::Quaterniond with_positive_scalar(const Eigen::Quaterniond& q) {
  return q.w() < 0.0 ? Eigen::Quaterniond(-q.w(), -q.x(), -q.y(), -q.z()) : q;
}

}  // namespace

void check_navigation_state(const NavigationState& s, std::string_view origin) {
  const GeodeticPosition& p = s.position;
  if (!std::isfinite(p.lat_rad) || std::abs(p.lat_rad) > kMaxNedLatitudeRad) {
    fail(origin, "latitude_rad = " + std::to_string(p.lat_rad) +
                     " is not finite or beyond the NED mechanisation's +-89.5 deg");
  }
  if (!std::isfinite(p.lon_rad) || std::abs(p.lon_rad) > units::kTwoPi) {
    fail(origin, "longitude_rad = " + std::to_string(p.lon_rad) + " is not finite or beyond 2 pi");
  }
  if (!std::isfinite(p.alt_m) || p.alt_m < kMinHeightM || p.alt_m > kMaxHeightM) {
    fail(origin, "height_m = " + std::to_string(p.alt_m) + " is not finite or outside [" +
                     std::to_string(kMinHeightM) + ", " + std::to_string(kMaxHeightM) + "]");
  }
  if (!s.velocity_ned_mps.allFinite() || s.velocity_ned_mps.norm() > kMaxSpeedMps) {
    fail(origin, "velocity_ned_mps is not finite or faster than " + std::to_string(kMaxSpeedMps));
  }
  const Eigen::Vector4d q = to_e0123(s.q_ned_from_body);
  if (!q.allFinite() || std::abs(q.norm() - 1.0) > 1e-6) {
    fail(origin, "q_ned_from_body is not finite or not of unit length (|q| = " +
                     std::to_string(q.norm()) + ")");
  }
}

NavigationErrors navigation_errors(const NavigationState& estimate, const NavigationState& truth) {
  const Eigen::Matrix3d ned_from_ecef =
      Wgs84::ned_from_ecef(truth.position.lat_rad, truth.position.lon_rad);
  NavigationErrors e;
  e.position_ned_m = ned_from_ecef * (Wgs84::ecef_from_geodetic(estimate.position) -
                                      Wgs84::ecef_from_geodetic(truth.position));
  e.horizontal_position_m = e.position_ned_m.head<2>().norm();
  e.velocity_ned_mps = estimate.velocity_ned_mps - truth.velocity_ned_mps;
  // C_est = C_err C_truth, C_err = exp([phi x]).
  e.attitude_ned_rad = rotation_vector_from_quaternion(
      estimate.q_ned_from_body.normalized() * truth.q_ned_from_body.normalized().conjugate());
  const EulerAngles est = euler_from_quaternion(estimate.q_ned_from_body);
  const EulerAngles tru = euler_from_quaternion(truth.q_ned_from_body);
  e.euler_rad = {wrap_pi(est.phi_rad - tru.phi_rad), wrap_pi(est.theta_rad - tru.theta_rad),
                 wrap_pi(est.psi_rad - tru.psi_rad)};
  return e;
}

NavigationState perturbed_state(const NavigationState& truth,
                                const Eigen::Vector3d& position_offset_ned_m,
                                const Eigen::Vector3d& velocity_offset_ned_mps,
                                const Eigen::Vector3d& tilt_ned_rad) {
  check_navigation_state(truth, "perturbed_state truth");
  if (!position_offset_ned_m.allFinite() || !velocity_offset_ned_mps.allFinite() ||
      !tilt_ned_rad.allFinite()) {
    throw std::invalid_argument("perturbed_state: an initial error is not finite");
  }
  const Eigen::Matrix3d ned_from_ecef =
      Wgs84::ned_from_ecef(truth.position.lat_rad, truth.position.lon_rad);
  NavigationState s = truth;
  s.position = Wgs84::geodetic_from_ecef(Wgs84::ecef_from_geodetic(truth.position) +
                                         ned_from_ecef.transpose() * position_offset_ned_m);
  s.velocity_ned_mps += velocity_offset_ned_mps;
  s.q_ned_from_body = with_positive_scalar(
      (quaternion_from_rotation_vector(tilt_ned_rad) * truth.q_ned_from_body).normalized());
  check_navigation_state(s, "perturbed_state result");
  return s;
}

Eigen::Quaterniond quaternion_from_rotation_vector(const Eigen::Vector3d& rotation_rad) {
  const double angle = rotation_rad.norm();
  if (angle < 1e-12) {
    // Second-order series: exact to rounding for such small angles.
    return Eigen::Quaterniond(1.0 - angle * angle / 8.0, 0.5 * rotation_rad.x(),
                              0.5 * rotation_rad.y(), 0.5 * rotation_rad.z());
  }
  const Eigen::Vector3d axis = rotation_rad / angle;
  const double s = std::sin(0.5 * angle);
  return Eigen::Quaterniond(std::cos(0.5 * angle), s * axis.x(), s * axis.y(), s * axis.z());
}

Eigen::Vector3d rotation_vector_from_quaternion(const Eigen::Quaterniond& q_in) {
  const Eigen::Quaterniond q = with_positive_scalar(q_in.normalized());
  const Eigen::Vector3d v = q.vec();
  const double s = v.norm();
  if (s < 1e-15) return 2.0 * v;
  return (2.0 * std::atan2(s, q.w()) / s) * v;
}

}  // namespace fedsim::nav
