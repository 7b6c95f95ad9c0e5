// The autopilot's inner loops: pitch attitude -> elevator and bank -> aileron (McLean,
// Automatic Flight Control Systems, 1990, ch. 9 "attitude control systems": attitude error
// with rate damping and an integral that carries the trim).
//
//   nose-up command  u = PI(s (theta_c - theta)) - s K_q (theta_dot - theta_dot_c)
//   pitch demand     = -u (+ = nose down): the elevator plus the trim (the caller subtracts the
//                      trim's position, so that the trim motor moving does not disturb the loop)
//   right-roll cmd   u = PI(s (phi_c - phi)) - s K_p (phi_dot - phi_dot_c),  aileron = +u
// The damping terms use the Euler-angle rates (the caller forms them from p, q, r): a steady
// turn has a body pitch rate psi_dot sin(phi) that the attitude does not, and damping it would
// pull the nose down in every turn. They damp the rate error against the command's own rate, so
// that a ramped command (the bank-rate limit) is followed without lag and without winding up
// the integral (which made a 10 deg bank ramp overshoot by 15 %).
// s is the dynamic-pressure gain schedule (reference CAS / CAS)^2: the surfaces' moments scale
// with qbar, so the loop gain stays at its design value. The schedule multiplies the error
// before the integral, so the integral holds the trim deflection itself (unchanged when the
// speed changes). Output limits -1..1 with conditional-integration anti-windup (common/control
// Pid); engage() is bumpless: the output continues from the surface's present command.
#pragma once

#include "common/control/pid.hpp"
#include "flight/model/afcs/afcs_parameters.hpp"

namespace fedsim::flight::afcs {

class PitchAttitudeLoop {
 public:
  PitchAttitudeLoop(const PitchLoopGains& gains, double dt_s);
  /// Takes over from the present pitch demand (elevator + trim) [-1..1] for this error and the
  /// pitch-rate error (theta_dot - theta_dot_c).
  void engage(double elevator, double pitch_error_rad, double pitch_rate_radps, double schedule);
  /// The pitch demand (elevator + trim) for the pitch command, attitude [rad] and the pitch-rate
  /// error [rad/s].
  double step(double pitch_command_rad, double pitch_rad, double pitch_rate_radps, double schedule);
  double elevator() const { return elevator_; }

 private:
  PitchLoopGains gains_;
  control::Pid pid_;
  double elevator_ = 0.0;
};

class RollAttitudeLoop {
 public:
  RollAttitudeLoop(const RollLoopGains& gains, double dt_s);
  void engage(double aileron, double bank_error_rad, double roll_rate_radps, double schedule);
  double step(double bank_command_rad, double bank_rad, double roll_rate_radps, double schedule);
  double aileron() const { return aileron_; }

 private:
  RollLoopGains gains_;
  control::Pid pid_;
  double aileron_ = 0.0;
};

}  // namespace fedsim::flight::afcs
