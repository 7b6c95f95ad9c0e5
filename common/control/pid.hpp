// PID controller, parallel form with a filtered derivative and output limits:
//   u = sat( Kp e + (Ki/s) e + Kd s/(tau_f s + 1) e ),  sat = clamp to [output_min, output_max].
// Input e: the error (setpoint - measurement, any unit); output u (the actuator command's unit).
// Sampled every dt_s.
//
// Discretisation (bilinear transform throughout): the integral term is the trapezoidal
// Integrator (c = 2/T); the derivative term is pre-warped at its roll-off 1/tau_f, so its gain
// there is exactly Kd/(tau_f sqrt 2); the roll-off must lie below Nyquist.
//
// Anti-windup (Astrom & Hagglund, Advanced PID Control, 2006, section 3.5), one of:
//  - kConditionalIntegration (default, no parameter): the integral is not advanced in a step
//    where the unsaturated output lies beyond a limit and the integral would move it further
//    out; it resumes as soon as the error would bring the output back.
//  - kBackCalculation: the integrand gets the tracking term (sat(u) - u)/T_t, which bleeds the
//    integral back while the output is saturated; T_t = tracking_time_constant_s >= dt_s (the
//    term uses the previous step's u, and that one-sample loop is stable for T_t > dt_s/2).
//
// Bumpless transfer: engage(e, u_now) sets the state so that the output equals u_now (the
// current command of whatever drove the actuator) for the error e: the derivative filter at
// rest on e (no kick), the integral at u_now - Kp e. The following steps continue from u_now at
// the rate Ki e the integral implies. (With Ki = 0 the integral is the constant offset engage set:
// a PD keeps the trim it took over.)
#pragma once

#include <limits>

#include "common/control/integrator.hpp"
#include "common/control/linear_section.hpp"

namespace fedsim::control {

enum class AntiWindup { kConditionalIntegration, kBackCalculation };

struct PidParameters {
  double proportional_gain = 0.0;      // Kp [output per error unit], finite
  double integral_gain_per_s = 0.0;    // Ki [output per (error unit s)], finite (0: no I term)
  double derivative_gain_s = 0.0;      // Kd [output s per error unit], finite (0: no D term)
  // tau_f [s] of the derivative roll-off Kd s/(tau_f s + 1): > dt_s/pi when Kd != 0.
  double derivative_filter_time_constant_s = 0.0;
  double output_min = -std::numeric_limits<double>::infinity();  // [output unit], not NaN
  double output_max = std::numeric_limits<double>::infinity();   // [output unit], > output_min
  AntiWindup anti_windup = AntiWindup::kConditionalIntegration;
  double tracking_time_constant_s = 0.0;  // T_t [s], >= dt_s for kBackCalculation only
};

/// A PI controller's parameters (no derivative term) with its output range: the form every
/// autopilot, autothrottle and rollout loop uses.
inline PidParameters pi_parameters(double proportional_gain, double integral_gain_per_s,
                                   double output_min, double output_max) {
  PidParameters p;
  p.proportional_gain = proportional_gain;
  p.integral_gain_per_s = integral_gain_per_s;
  p.output_min = output_min;
  p.output_max = output_max;
  return p;
}

class Pid {
 public:
  /// Checks every parameter (std::invalid_argument naming it) and dt_s > 0.
  Pid(const PidParameters& parameters, double dt_s);

  /// One step with error e (finite): the limited output.
  double step(double error);
  double output() const { return output_; }

  /// At rest: every term zero.
  void reset();
  /// Bumpless engagement: output() becomes `output` (within the output limits, else
  /// std::invalid_argument) for the error `error`, and the next steps continue from it.
  void engage(double error, double output);

  /// The terms of the last step (before the limit): P = Kp e, I, D.
  double proportional() const { return proportional_; }
  double integral() const { return integral_.output(); }
  double derivative() const { return derivative_.output(); }
  /// True when the last output was limited.
  bool saturated() const { return saturated_; }
  const PidParameters& parameters() const { return parameters_; }

 private:
  double advance_integral(double error);

  PidParameters parameters_;
  Integrator integral_;            // unit gain: integrates Ki e (+ the tracking term)
  LinearSection<1> derivative_;    // Kd s/(tau_f s + 1), pre-warped at 1/tau_f
  double proportional_ = 0.0;
  double unlimited_output_ = 0.0;  // P + I + D of the last step
  double output_ = 0.0;            // sat(P + I + D)
  bool saturated_ = false;
};

}  // namespace fedsim::control
