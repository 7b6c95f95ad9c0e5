// The path loop: a flight-path-angle command -> a pitch-attitude command, shared by every path
// mode (altitude hold and capture, V/S, level change, G/S, flare, go-around).
//
//   theta_c = PI(gamma_c - gamma) + (1 - cos(phi)) (s K_turn - alpha),  limited to [pitch_min, pitch_max]
//
// gamma = atan2(climb rate, ground speed): the path over the ground (a glide path is fixed to
// the ground; in a headwind the air path is steeper). At constant angle of attack a change of
// pitch is a change of path, but the path follows with the lag 1/Z_alpha (2.3 s for the 737 at
// approach): the integral gain is the proportional gain over that lag, cancelling the path
// lag's pole so that the loop is close to a pure integrator with crossover Kp / tau (~0.4 rad/s,
// below the pitch loop's ~1.3 rad/s).
// The turn term is the pitch a level turn at bank phi needs beyond the wings-level one: the lift
// must grow by n = 1/cos(phi), i.e. the angle of attack from alpha to alpha + (n - 1) K with
// K = CL / CL_alpha (the angle of attack above zero lift), while with the wings banked the
// pitch attitude of a level path is alpha cos(phi) (theta = gamma + alpha cos(phi) to first order):
// dtheta = (alpha + (n - 1) K) cos(phi) - alpha = (1 - cos(phi)) (K - alpha). CL ~ 1/qbar, so K is
// CL / CL_alpha at the reference CAS (the 737 pack at 145 KCAS, 48.5 t: CL 1.38 / 4.35 per rad:
// 18 deg) times the gain schedule s. At 30 deg bank: +1.8 deg at 145 KCAS (alpha 5 deg), +0.4
// deg at 250 KCAS (alpha 3.2 deg); the altitude error need not build up first.
// The integral holds the angle of attack (theta = gamma + alpha in still air); engage() starts
// it from the present pitch so that a path mode takes over without a pitch step.
#pragma once

#include "common/control/pid.hpp"
#include "flight/model/afcs/afcs_parameters.hpp"

namespace fedsim::flight::afcs {

/// The path over the ground [rad]: atan2(climb rate, ground speed), 0 below 1 m/s.
double flight_path_angle_rad(double vertical_speed_mps, double ground_speed_mps);

class FlightPathLoop {
 public:
  FlightPathLoop(const FlightPathGains& gains, double dt_s);
  /// Continue from the present pitch command for the present path error and bank.
  void engage(double pitch_command_rad, double path_error_rad, double bank_rad, double schedule,
              double alpha_rad);
  /// The pitch command [rad] for gamma_c, gamma [rad] and the bank [rad]; upper limit lowered
  /// to `pitch_max_rad` when it is below the gains' own (go-around).
  /// `feedforward_rad` is added to the command outside the PI (the flare's lead).
  double step(double path_command_rad, double path_rad, double bank_rad, double pitch_max_rad,
              double schedule, double alpha_rad, double feedforward_rad = 0.0);
  double pitch_command_rad() const { return pitch_command_rad_; }

 private:
  double turn_compensation_rad(double bank_rad, double schedule, double alpha_rad) const;
  FlightPathGains gains_;
  control::Pid pid_;
  double pitch_command_rad_ = 0.0;
};

}  // namespace fedsim::flight::afcs
