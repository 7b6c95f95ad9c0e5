// Checks of the physical parameters every control-law block is built from, and of the inputs it
// is stepped with. A bad value throws std::invalid_argument naming the block, the parameter and
// the value ("FirstOrderLag: time_constant_s = -1 must be positive"), so that a wrong pack field
// or option is found where it entered rather than as a NaN in the autopilot later.
#pragma once

#include <cmath>
#include <string_view>

namespace fedsim::control {

/// value must be finite (not NaN, not +-infinity).
void require_finite(std::string_view block, std::string_view parameter, double value);
/// value must be finite and > 0.
void require_positive(std::string_view block, std::string_view parameter, double value);
/// value must be finite and >= 0.
void require_non_negative(std::string_view block, std::string_view parameter, double value);
/// value must be finite and non-zero.
void require_non_zero(std::string_view block, std::string_view parameter, double value);
/// The sample period dt_s must be finite and > 0.
void require_sample_period(std::string_view block, double dt_s);
/// A limit pair: neither NaN (an infinite limit means "no limit"), lower < upper.
void require_limits(std::string_view block, std::string_view lower_name, double lower,
                    std::string_view upper_name, double upper);
/// A characteristic frequency (what = how it is formed from the parameters, e.g.
/// "1/time_constant_s") must lie below the Nyquist frequency pi/dt_s, where the bilinear
/// transform can place it (its pre-warped map c*tan(w dt/2) is finite only below pi/dt_s).
void require_below_nyquist(std::string_view block, std::string_view what, double frequency_radps,
                           double dt_s);
/// value (a duration [s]) must be at least the sample period dt_s: "must be at least dt_s = ...".
void require_at_least_sample_period(std::string_view block, std::string_view parameter,
                                    double value, double dt_s);
/// value must be finite, > 0 and <= upper.
void require_positive_at_most(std::string_view block, std::string_view parameter, double value,
                              double upper);
/// A value a block is reset to must lie within its limits [lower, upper] ("lies outside the
/// limits [lower, upper]"); NaN is not caught here (require_finite first).
void require_within_limits(std::string_view block, std::string_view parameter, double value,
                           double lower, double upper);
/// The argument of a block's method (reset, reset_to_input) must be finite; the message names
/// "<block>::<method>" (built only when the check fails).
void require_finite_argument(std::string_view block, std::string_view method,
                             std::string_view parameter, double value);

/// Thrown by require_finite_input; out of line so that the check in step() stays one branch.
[[noreturn]] void throw_non_finite_input(std::string_view block, double input);

/// The value a block is stepped with must be finite: a NaN would poison the block's state for
/// good. Cheap (one comparison), allocation-free unless it throws.
inline void require_finite_input(std::string_view block, double input) {
  if (!std::isfinite(input)) [[unlikely]] {
    throw_non_finite_input(block, input);
  }
}

}  // namespace fedsim::control
