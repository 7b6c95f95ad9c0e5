// The classical washout algorithm (Reid & Nahon 1985, UTIAS Report 296; Nahon & Reid 1990,
// "Simulator motion-drive algorithms: a designer's perspective", J. Guidance 13(2)): the motion
// cues a platform of limited travel can give for the aircraft's specific force and angular rate
// at the pilot's head, as the platform pose to command. Sampled every dt_s (the frame).
//
// Input (WashoutInput): the specific force at the pilot's eye point and the body rates, both in
// aircraft body axes (AircraftState.specific_force_eye_body_mps2 and omega_body_radps), SI.
// Output (WashoutOutput): the pose of the platform (frames I and P, platform_pose.hpp; the pilot's
// head is taken at the MRP), the acceleration and the specific force it delivers there.
//
// Per frame, with beta_s the platform's Euler angles of the previous frame, R(beta) = i_from_p:
//  1. Scaling and limiting: f_ref = (0, 0, -g) is the 1-g specific force of level flight;
//     f_s = f_ref + clamp(K (f - f_ref), +-specific_force_limit) per axis, so a gain < 1 scales
//     the manoeuvre, not gravity.
//  2. Gravity alignment: a_i = R(beta_s) f_s + g_i, g_i = (0, 0, g): the acceleration the
//     platform would need in I to reproduce f_s with its present attitude (0 in level flight).
//  3. Translational channel: per axis a_hp = s^2/(s^2 + 2 zeta wn s + wn^2) . s/(s + wb) . a_i
//     (third-order high-pass), x = integral integral a_hp. A sustained a_i leaves no
//     displacement: x/a_i = s/((s^2 + 2 zeta wn s + wn^2)(s + wb)) has a zero at s = 0.
//  4. Tilt coordination: f_lp = wn^2/(s^2 + 2 zeta wn s + wn^2) K_tilt f (x and y);
//     theta_tilt = asin(f_lp,x / g), phi_tilt = -asin(f_lp,y / (g cos theta_tilt)) (the attitude
//     at which gravity alone gives f_lp: at rest f_p = (g sin theta, -g sin phi cos theta, ...)),
//     clamped to +-angle_limit and rate-limited to rate_limit (below the pilot's threshold).
//  5. Rotational channel: Euler rates beta_dot = T(beta_s) K omega (T: body rates to 3-2-1 Euler
//     rates, seed eqs 3.48-3.50), each through s^2/(s^2 + 2 zeta wn s + wn^2) and integrated: a
//     sustained rate leaves no angle.
//  6. beta_s = beta_hp + (phi_tilt, theta_tilt, 0).
// The filters are fedsim::control blocks (bilinear, pre-warped at their characteristic
// frequencies); the integrators are trapezoidal.
//
// Delivered cue of the commanded pose (before the jacks): f_cue,p = R(beta_s)^T (a_hp - g_i);
// omega_cue,p = T(beta_s)^-1 beta_s_dot.
#pragma once

#include <Eigen/Core>
#include <array>

#include "common/control/integrator.hpp"
#include "common/control/rate_limiter.hpp"
#include "common/control/second_order_filters.hpp"
#include "common/control/washout.hpp"
#include "motion/model/platform_pose.hpp"
#include "motion/model/washout_parameters.hpp"

namespace fedsim::motion {

struct WashoutInput {
  Eigen::Vector3d specific_force_body_mps2 = {0.0, 0.0, -9.80665};  // at the pilot's head [m/s^2]
  Eigen::Vector3d omega_body_radps = Eigen::Vector3d::Zero();       // body rates [rad/s]
};

struct WashoutOutput {
  PlatformPose pose;                                              // pose to command (before limits)
  Eigen::Vector3d acceleration_i_mps2 = Eigen::Vector3d::Zero();  // a_hp: MRP acceleration, I
  Eigen::Vector3d specific_force_cue_p_mps2 = Eigen::Vector3d::Zero();  // delivered, P [m/s^2]
  Eigen::Vector3d omega_cue_p_radps = Eigen::Vector3d::Zero();          // delivered rate, P [rad/s]
  double tilt_roll_rad = 0.0;                                           // phi_tilt [rad]
  double tilt_pitch_rad = 0.0;                                          // theta_tilt [rad]
  bool tilt_rate_limited = false;
};

class ClassicalWashout {
 public:
  /// Parameters validated for dt_s (std::invalid_argument). Starts at rest at neutral under
  /// level 1-g flight (as after reset(WashoutInput{})).
  ClassicalWashout(const ClassicalWashoutParameters& parameters, double dt_s);

  /// One frame; inputs must be finite (std::invalid_argument, the state untouched).
  WashoutOutput step(const WashoutInput& input);

  /// The platform at neutral, every filter steady under `input` held: the translational and
  /// rotational channels give no output while it is held; the tilt's low-pass is steady, its
  /// rate limiter at 0, so a sustained force in `input` tilts the cab in at the rate limit.
  void reset(const WashoutInput& input);

  const ClassicalWashoutParameters& parameters() const { return parameters_; }
  double dt_s() const { return dt_s_; }
  const WashoutOutput& output() const { return output_; }

 private:
  struct TranslationalAxis {
    control::SecondOrderHighPass high_pass;
    control::Washout washout;
    control::Integrator velocity;
    control::Integrator position;
  };
  struct RotationalAxis {
    control::SecondOrderHighPass high_pass;
    control::Integrator angle;
  };

  static TranslationalAxis make_axis(const TranslationalChannelParameters& p, double dt_s);
  static RotationalAxis make_axis(const RotationalChannelParameters& p, double dt_s);

  Eigen::Vector3d scaled_specific_force(const Eigen::Vector3d& f) const;
  Eigen::Vector3d gravity_aligned_acceleration(const Eigen::Vector3d& f_scaled) const;
  Eigen::Vector2d tilt_input(const Eigen::Vector3d& f) const;
  Eigen::Vector3d scaled_euler_rates(const Eigen::Vector3d& omega) const;
  void step_tilt(const Eigen::Vector2d& f_xy);

  ClassicalWashoutParameters parameters_;
  double dt_s_;
  std::array<TranslationalAxis, 3> translational_;
  std::array<RotationalAxis, 3> rotational_;
  std::array<control::SecondOrderLowPass, 2> tilt_low_pass_;  // x, y specific force
  control::RateLimiter tilt_pitch_;
  control::RateLimiter tilt_roll_;
  WashoutOutput output_;
};

/// T(beta): body rates -> 3-2-1 Euler rates (phi_dot, theta_dot, psi_dot); singular at
/// theta = +-90 deg (not reached: the platform's pitch is limited to well below).
Eigen::Matrix3d euler_rates_from_body_rates(const EulerAngles& attitude);

}  // namespace fedsim::motion
