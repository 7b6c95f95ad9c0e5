#include "motion/model/classical_washout.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "common/math/rotation.hpp"

namespace fedsim::motion {
namespace {

void require_finite_input(const WashoutInput& input) {
  if (!input.specific_force_body_mps2.allFinite()) {
    throw std::invalid_argument("ClassicalWashout: specific_force_body_mps2 is not finite");
  }
  if (!input.omega_body_radps.allFinite()) {
    throw std::invalid_argument("ClassicalWashout: omega_body_radps is not finite");
  }
}

// The attitude's inverse kinematic matrix: body rates from 3-2-1 Euler rates.
Eigen::Matrix3d body_rates_from_euler_rates(const EulerAngles& a) {
  const double sp = std::sin(a.phi_rad);
  const double cp = std::cos(a.phi_rad);
  const double st = std::sin(a.theta_rad);
  const double ct = std::cos(a.theta_rad);
  Eigen::Matrix3d m;
  m << 1.0, 0.0, -st, 0.0, cp, sp * ct, 0.0, -sp, cp * ct;
  return m;
}

}  // namespace

Eigen::Matrix3d euler_rates_from_body_rates(const EulerAngles& a) {
  const double sp = std::sin(a.phi_rad);
  const double cp = std::cos(a.phi_rad);
  const double tt = std::tan(a.theta_rad);
  const double sec = 1.0 / std::cos(a.theta_rad);
  Eigen::Matrix3d t;
  t << 1.0, sp * tt, cp * tt, 0.0, cp, -sp, 0.0, sp * sec, cp * sec;  // seed eqs 3.48-3.50
  return t;
}

ClassicalWashout::ClassicalWashout(const ClassicalWashoutParameters& parameters, double dt_s)
    : parameters_((validate(parameters, dt_s), parameters)),
      dt_s_(dt_s),
      translational_{make_axis(parameters.translational[0], dt_s),
                     make_axis(parameters.translational[1], dt_s),
                     make_axis(parameters.translational[2], dt_s)},
      rotational_{make_axis(parameters.rotational[0], dt_s),
                  make_axis(parameters.rotational[1], dt_s),
                  make_axis(parameters.rotational[2], dt_s)},
      tilt_low_pass_{control::SecondOrderLowPass(parameters.tilt.natural_frequency_radps,
                                                 parameters.tilt.damping_ratio, dt_s),
                     control::SecondOrderLowPass(parameters.tilt.natural_frequency_radps,
                                                 parameters.tilt.damping_ratio, dt_s)},
      tilt_pitch_(parameters.tilt.rate_limit_radps, dt_s),
      tilt_roll_(parameters.tilt.rate_limit_radps, dt_s) {
  reset(WashoutInput{{0.0, 0.0, -parameters.gravity_mps2}, Eigen::Vector3d::Zero()});
}

ClassicalWashout::TranslationalAxis ClassicalWashout::make_axis(
    const TranslationalChannelParameters& p, double dt_s) {
  return TranslationalAxis{
      control::SecondOrderHighPass(p.natural_frequency_radps, p.damping_ratio, dt_s),
      control::Washout(1.0 / p.break_frequency_radps, dt_s), control::Integrator(1.0, dt_s),
      control::Integrator(1.0, dt_s)};
}

ClassicalWashout::RotationalAxis ClassicalWashout::make_axis(const RotationalChannelParameters& p,
                                                             double dt_s) {
  return RotationalAxis{
      control::SecondOrderHighPass(p.natural_frequency_radps, p.damping_ratio, dt_s),
      control::Integrator(1.0, dt_s)};
}

Eigen::Vector3d ClassicalWashout::scaled_specific_force(const Eigen::Vector3d& f) const {
  const double limit = parameters_.specific_force_limit_mps2;
  const Eigen::Vector3d f_ref(0.0, 0.0, -parameters_.gravity_mps2);
  Eigen::Vector3d scaled;
  for (int i = 0; i < 3; ++i) {
    const double deviation = parameters_.translational[i].gain * (f(i) - f_ref(i));
    scaled(i) = f_ref(i) + std::clamp(deviation, -limit, limit);
  }
  return scaled;
}

Eigen::Vector3d ClassicalWashout::gravity_aligned_acceleration(
    const Eigen::Vector3d& f_scaled) const {
  const Eigen::Vector3d g_i(0.0, 0.0, parameters_.gravity_mps2);
  return dcm_from_euler(output_.pose.attitude) * f_scaled + g_i;
}

Eigen::Vector2d ClassicalWashout::tilt_input(const Eigen::Vector3d& f) const {
  const double limit = parameters_.specific_force_limit_mps2;
  const double gain = parameters_.tilt.gain;
  return {std::clamp(gain * f.x(), -limit, limit), std::clamp(gain * f.y(), -limit, limit)};
}

Eigen::Vector3d ClassicalWashout::scaled_euler_rates(const Eigen::Vector3d& omega) const {
  Eigen::Vector3d scaled;
  for (int i = 0; i < 3; ++i) scaled(i) = parameters_.rotational[i].gain * omega(i);
  return euler_rates_from_body_rates(output_.pose.attitude) * scaled;
}

void ClassicalWashout::step_tilt(const Eigen::Vector2d& f_xy) {
  const double g = parameters_.gravity_mps2;
  const double sin_limit = std::sin(parameters_.tilt.angle_limit_rad);
  const double f_x = tilt_low_pass_[0].step(f_xy.x());
  const double f_y = tilt_low_pass_[1].step(f_xy.y());
  if (!parameters_.tilt.enabled) {
    output_.tilt_pitch_rad = tilt_pitch_.step(0.0);
    output_.tilt_roll_rad = tilt_roll_.step(0.0);
    output_.tilt_rate_limited = tilt_pitch_.limited() || tilt_roll_.limited();
    return;
  }
  const double pitch_target = std::asin(std::clamp(f_x / g, -sin_limit, sin_limit));
  output_.tilt_pitch_rad = tilt_pitch_.step(pitch_target);
  const double roll_sine = -f_y / (g * std::cos(output_.tilt_pitch_rad));
  output_.tilt_roll_rad = tilt_roll_.step(std::asin(std::clamp(roll_sine, -sin_limit, sin_limit)));
  output_.tilt_rate_limited = tilt_pitch_.limited() || tilt_roll_.limited();
}

WashoutOutput ClassicalWashout::step(const WashoutInput& input) {
  require_finite_input(input);
  const Eigen::Vector3d f_scaled = scaled_specific_force(input.specific_force_body_mps2);
  const Eigen::Vector3d a_i = gravity_aligned_acceleration(f_scaled);
  const Eigen::Vector3d euler_rates = scaled_euler_rates(input.omega_body_radps);
  const double previous_tilt_roll_rad = output_.tilt_roll_rad;
  const double previous_tilt_pitch_rad = output_.tilt_pitch_rad;

  for (int i = 0; i < 3; ++i) {
    TranslationalAxis& axis = translational_[i];
    const double a_hp = axis.washout.step(axis.high_pass.step(a_i(i)));
    output_.acceleration_i_mps2(i) = a_hp;
    output_.pose.position_i_m(i) = axis.position.step(axis.velocity.step(a_hp));
  }
  step_tilt(tilt_input(input.specific_force_body_mps2));

  Eigen::Vector3d angle_rates;  // of the whole Euler angles (high-pass + tilt) [rad/s]
  Eigen::Vector3d angles;
  for (int i = 0; i < 3; ++i) {
    const double rate = rotational_[i].high_pass.step(euler_rates(i));
    angles(i) = rotational_[i].angle.step(rate);
    angle_rates(i) = rate;
  }
  angles(0) += output_.tilt_roll_rad;
  angles(1) += output_.tilt_pitch_rad;
  angle_rates(0) += (output_.tilt_roll_rad - previous_tilt_roll_rad) / dt_s_;
  angle_rates(1) += (output_.tilt_pitch_rad - previous_tilt_pitch_rad) / dt_s_;
  output_.pose.attitude = EulerAngles{angles(0), angles(1), angles(2)};

  const Eigen::Vector3d g_i(0.0, 0.0, parameters_.gravity_mps2);
  output_.specific_force_cue_p_mps2 =
      dcm_from_euler(output_.pose.attitude).transpose() * (output_.acceleration_i_mps2 - g_i);
  output_.omega_cue_p_radps = body_rates_from_euler_rates(output_.pose.attitude) * angle_rates;
  return output_;
}

void ClassicalWashout::reset(const WashoutInput& input) {
  require_finite_input(input);
  output_ = WashoutOutput{};
  const Eigen::Vector3d a_i =
      gravity_aligned_acceleration(scaled_specific_force(input.specific_force_body_mps2));
  const Eigen::Vector3d euler_rates = scaled_euler_rates(input.omega_body_radps);
  for (int i = 0; i < 3; ++i) {
    translational_[i].high_pass.reset_to_input(a_i(i));
    translational_[i].washout.reset_to_input(0.0);
    translational_[i].velocity.reset(0.0);
    translational_[i].position.reset(0.0);
    rotational_[i].high_pass.reset_to_input(euler_rates(i));
    rotational_[i].angle.reset(0.0);
  }
  const Eigen::Vector2d f_xy = tilt_input(input.specific_force_body_mps2);
  tilt_low_pass_[0].reset_to_input(f_xy.x());
  tilt_low_pass_[1].reset_to_input(f_xy.y());
  tilt_pitch_.reset(0.0);
  tilt_roll_.reset(0.0);
  const Eigen::Vector3d g_i(0.0, 0.0, parameters_.gravity_mps2);
  output_.specific_force_cue_p_mps2 = -g_i;
}

}  // namespace fedsim::motion
