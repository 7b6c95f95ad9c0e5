// Integrator with limits  H(s) = K / s,  y in [lower_limit, upper_limit].
// Input u (any unit), output y [unit of u times K times s], sampled every dt_s.
//
// Discretised by the bilinear transform with c = 2/T (no pre-warping: 1/s has no corner), i.e.
// the trapezoidal rule  y_n = y_{n-1} + (K T/2)(u_n + u_{n-1}); its frequency response is
// K / (j (2/T) tan(w T/2)).
//
// Anti-windup by clamping the state: the state is the output, and it never leaves the limits.
// A step that would carry it past a limit ends at the limit, and while it sits there the
// integrand of that step counts as zero (the state did not move), so the trapezoid's memory of
// the input that pushed it into the limit is forgotten: when the input reverses the output
// leaves the limit in the very next step. (Without this the state would have to "unwind" the
// excess first: the windup of an integrator followed by a separate saturation.)
//
// Starts at output 0 (clamped into the limits when they exclude 0). peek() and hold() let a
// caller (the PID's conditional integration) decide per step whether to integrate.
#pragma once

#include <limits>

namespace fedsim::control {

class Integrator {
 public:
  /// gain_per_s: K [output per (input s)], finite, non-zero; dt_s > 0; limits: not NaN,
  /// lower_limit < upper_limit (+-infinity: no limit on that side).
  Integrator(double gain_per_s, double dt_s,
             double lower_limit = -std::numeric_limits<double>::infinity(),
             double upper_limit = std::numeric_limits<double>::infinity());

  /// One trapezoidal step with input u (finite); the output, clamped to the limits.
  double step(double u);
  /// The output step(u) would give, without changing the state.
  double peek(double u) const;
  /// A step with no integration: the output stays, the integrand memory is cleared.
  void hold();
  double output() const { return output_; }

  /// Sets the output to y (within the limits, else std::invalid_argument). previous_input is
  /// the input taken as the last one integrated (the trapezoid's memory): pass the input that
  /// will be applied next to continue smoothly, or leave 0 for a start at rest.
  void reset(double y, double previous_input = 0.0);

  /// True when the last step ended on a limit.
  bool limited() const { return limited_; }
  double gain_per_s() const { return gain_per_s_; }
  double lower_limit() const { return lower_limit_; }
  double upper_limit() const { return upper_limit_; }

 private:
  double unclamped(double u) const;

  double gain_per_s_;
  double half_step_gain_;  // K T/2: the bilinear transform's b0 = b1
  double lower_limit_;
  double upper_limit_;
  double output_ = 0.0;
  double previous_input_ = 0.0;  // u_{n-1} for the trapezoid; 0 after a limited step or hold
  bool limited_ = false;
};

}  // namespace fedsim::control
