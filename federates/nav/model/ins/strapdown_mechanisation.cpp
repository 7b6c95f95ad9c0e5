// Strapdown NED mechanisation: attitude, velocity and position updates.
#include "federates/nav/model/ins/strapdown_mechanisation.hpp"

#include "federates/nav/model/ins/navigation_earth.hpp"

#include <cmath>
#include <stdexcept>
#include <string>

namespace fedsim::nav {

namespace {

constexpr double kMaxUpdateIntervalS = 60.0;

Eigen::Quaterniond normalised_positive(const Eigen::Quaterniond& q) {
  const Eigen::Quaterniond n = q.normalized();
  return n.w() < 0.0 ? Eigen::Quaterniond(-n.w(), -n.x(), -n.y(), -n.z()) : n;
}

double wrap_longitude(double lon_rad) { return wrap_pi(lon_rad); }

}  // namespace

StrapdownMechanisation::StrapdownMechanisation(const NavigationState& initial)
    : state_(initial) {
  check_navigation_state(initial, "StrapdownMechanisation initial state");
  state_.q_ned_from_body = normalised_positive(initial.q_ned_from_body);
}

void StrapdownMechanisation::update(const ImuSample& measured, double dt_s,
                                    const VerticalChannelCorrection& vertical) {
  if (!std::isfinite(dt_s) || dt_s <= 0.0 || dt_s > kMaxUpdateIntervalS) {
    throw std::invalid_argument("StrapdownMechanisation::update: dt_s = " + std::to_string(dt_s) +
                                " must be in (0, 60] s");
  }
  check_imu_sample(measured, "StrapdownMechanisation::update");
  if (!std::isfinite(vertical.height_rate_mps) || !std::isfinite(vertical.down_acceleration_mps2)) {
    throw std::invalid_argument("StrapdownMechanisation::update: vertical correction not finite");
  }

  const double lat0 = state_.position.lat_rad;
  const double h0 = state_.position.alt_m;
  const Eigen::Vector3d v0 = state_.velocity_ned_mps;
  const Eigen::Quaterniond q0 = state_.q_ned_from_body;

  // (D1) rotation vectors of the body (w.r.t. inertial) and of the NED frame over the interval.
  const Eigen::Vector3d omega_ie = earth_rate_ned(lat0);
  const Eigen::Vector3d omega_en0 = transport_rate_ned(lat0, h0, v0);
  const Eigen::Vector3d alpha = measured.omega_body_radps * dt_s;
  const Eigen::Vector3d zeta = (omega_ie + omega_en0) * dt_s;

  // (D2) specific force resolved with the mid-interval attitude.
  const Eigen::Quaterniond q_mid = quaternion_from_rotation_vector(-0.5 * zeta) * q0 *
                                   quaternion_from_rotation_vector(0.5 * alpha);
  const Eigen::Vector3d f_ned = q_mid * measured.specific_force_body_mps2;

  // (D3) velocity: specific force, Coriolis + transport, gravity, vertical aiding.
  const Eigen::Vector3d g_ned = gravity_ned(state_.position);
  Eigen::Vector3d v_dot = f_ned - (2.0 * omega_ie + omega_en0).cross(v0) + g_ned;
  v_dot.z() += vertical.down_acceleration_mps2;
  const Eigen::Vector3d v1 = v0 + v_dot * dt_s;

  // (D4) position by the trapezoidal rule (height first: the radii use the new height).
  const double h1 = h0 - 0.5 * dt_s * (v0.z() + v1.z()) + vertical.height_rate_mps * dt_s;
  const LocalRadii r0 = local_radii(lat0, h0);
  const double rn0_new_h = Wgs84::meridian_radius_m(lat0) + h1;
  const double lat1 = lat0 + 0.5 * dt_s * (v0.x() / r0.meridian_plus_height_m + v1.x() / rn0_new_h);
  if (!std::isfinite(lat1) || std::abs(lat1) > kMaxNedLatitudeRad) {
    throw std::domain_error("StrapdownMechanisation: latitude " + std::to_string(lat1) +
                            " rad is beyond the NED mechanisation's +-89.5 deg");
  }
  const LocalRadii r1 = local_radii(lat1, h1);
  const double lon1 =
      state_.position.lon_rad +
      0.5 * dt_s *
          (v0.y() / (r0.transverse_plus_height_m * std::cos(lat0)) +
           v1.y() / (r1.transverse_plus_height_m * std::cos(lat1)));

  // (D5) attitude: body rotation, then the NED frame's rotation (mean transport rate).
  const Eigen::Vector3d omega_en1 = transport_rate_ned(lat1, h1, v1);
  const Eigen::Vector3d zeta_mean = (omega_ie + 0.5 * (omega_en0 + omega_en1)) * dt_s;
  const Eigen::Quaterniond q1 = quaternion_from_rotation_vector(-zeta_mean) * q0 *
                                quaternion_from_rotation_vector(alpha);

  state_.position = {lat1, wrap_longitude(lon1), h1};
  state_.velocity_ned_mps = v1;
  state_.q_ned_from_body = normalised_positive(q1);
  if (!state_.velocity_ned_mps.allFinite() || !std::isfinite(h1)) {
    throw std::domain_error("StrapdownMechanisation: the state became non-finite");
  }
}

}  // namespace fedsim::nav
