#include "common/control/parameter_checks.hpp"

#include <sstream>
#include <stdexcept>
#include <string>

#include "common/units/units.hpp"

namespace fedsim::control {
namespace {

[[noreturn]] void fail(std::string_view block, std::string_view parameter, double value,
                       std::string_view problem) {
  std::ostringstream message;
  message.precision(9);
  message << block << ": " << parameter << " = " << value << " " << problem;
  throw std::invalid_argument(message.str());
}

}  // namespace

void require_finite(std::string_view block, std::string_view parameter, double value) {
  if (!std::isfinite(value)) fail(block, parameter, value, "must be finite");
}

void require_positive(std::string_view block, std::string_view parameter, double value) {
  require_finite(block, parameter, value);
  if (!(value > 0.0)) fail(block, parameter, value, "must be positive");
}

void require_non_negative(std::string_view block, std::string_view parameter, double value) {
  require_finite(block, parameter, value);
  if (!(value >= 0.0)) fail(block, parameter, value, "must not be negative");
}

void require_non_zero(std::string_view block, std::string_view parameter, double value) {
  require_finite(block, parameter, value);
  if (value == 0.0) fail(block, parameter, value, "must not be zero");
}

void require_sample_period(std::string_view block, double dt_s) {
  require_positive(block, "dt_s", dt_s);
}

void require_limits(std::string_view block, std::string_view lower_name, double lower,
                    std::string_view upper_name, double upper) {
  if (std::isnan(lower)) fail(block, lower_name, lower, "must not be NaN");
  if (std::isnan(upper)) fail(block, upper_name, upper, "must not be NaN");
  if (!(lower < upper)) {
    std::ostringstream problem;
    problem.precision(9);
    problem << "must be below " << upper_name << " = " << upper;
    fail(block, lower_name, lower, problem.str());
  }
}

void require_below_nyquist(std::string_view block, std::string_view what, double frequency_radps,
                           double dt_s) {
  const double nyquist_radps = units::kPi / dt_s;
  if (!(frequency_radps < nyquist_radps)) {
    std::ostringstream problem;
    problem.precision(9);
    problem << "rad/s must be below the Nyquist frequency pi/dt_s = " << nyquist_radps
            << " rad/s (dt_s = " << dt_s << ")";
    fail(block, what, frequency_radps, problem.str());
  }
}

void require_at_least_sample_period(std::string_view block, std::string_view parameter,
                                    double value, double dt_s) {
  if (value < dt_s) {
    std::ostringstream problem;
    problem.precision(9);
    problem << "must be at least dt_s = " << dt_s;
    fail(block, parameter, value, problem.str());
  }
}

void require_positive_at_most(std::string_view block, std::string_view parameter, double value,
                              double upper) {
  require_positive(block, parameter, value);
  if (value > upper) {
    std::ostringstream problem;
    problem.precision(9);
    problem << "must be at most " << upper;
    fail(block, parameter, value, problem.str());
  }
}

void require_within_limits(std::string_view block, std::string_view parameter, double value,
                           double lower, double upper) {
  if (value < lower || value > upper) {
    std::ostringstream problem;
    problem.precision(9);
    problem << "lies outside the limits [" << lower << ", " << upper << "]";
    fail(block, parameter, value, problem.str());
  }
}

void require_finite_argument(std::string_view block, std::string_view method,
                             std::string_view parameter, double value) {
  if (!std::isfinite(value)) [[unlikely]] {
    std::string where(block);
    where.append("::").append(method);
    fail(where, parameter, value, "must be finite");
  }
}

void throw_non_finite_input(std::string_view block, double input) {
  fail(block, "input", input, "must be finite");
}

}  // namespace fedsim::control
