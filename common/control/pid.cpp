#include "common/control/pid.hpp"

#include <algorithm>
#include <sstream>
#include <stdexcept>

#include "common/control/bilinear.hpp"
#include "common/control/parameter_checks.hpp"

namespace fedsim::control {
namespace {

constexpr const char* kBlock = "Pid";

void check(const PidParameters& p, double dt_s) {
  require_sample_period(kBlock, dt_s);
  require_finite(kBlock, "proportional_gain", p.proportional_gain);
  require_finite(kBlock, "integral_gain_per_s", p.integral_gain_per_s);
  require_finite(kBlock, "derivative_gain_s", p.derivative_gain_s);
  require_non_negative(kBlock, "derivative_filter_time_constant_s",
                       p.derivative_filter_time_constant_s);
  if (p.derivative_gain_s != 0.0) {
    require_positive(kBlock, "derivative_filter_time_constant_s",
                     p.derivative_filter_time_constant_s);
    require_below_nyquist(kBlock, "roll-off 1/derivative_filter_time_constant_s",
                          1.0 / p.derivative_filter_time_constant_s, dt_s);
  }
  require_limits(kBlock, "output_min", p.output_min, "output_max", p.output_max);
  if (p.anti_windup == AntiWindup::kBackCalculation) {
    require_positive(kBlock, "tracking_time_constant_s", p.tracking_time_constant_s);
    require_at_least_sample_period(kBlock, "tracking_time_constant_s", p.tracking_time_constant_s,
                                   dt_s);
  }
}

LinearSection<1> derivative_section(const PidParameters& p, double dt_s) {
  if (p.derivative_gain_s == 0.0) {
    return LinearSection<1>(DiscreteTransferFunction<1>{{0.0, 0.0}, {1.0, 0.0}});  // y = 0
  }
  const double tau_f = p.derivative_filter_time_constant_s;
  const ContinuousTransferFunction<1> h{{0.0, p.derivative_gain_s}, {1.0, tau_f}};
  return LinearSection<1>(bilinear(h, prewarped_tustin_constant_per_s(dt_s, 1.0 / tau_f)));
}

const PidParameters& checked(const PidParameters& p, double dt_s) {
  check(p, dt_s);
  return p;
}

}  // namespace

Pid::Pid(const PidParameters& parameters, double dt_s)
    : parameters_(checked(parameters, dt_s)),
      integral_(1.0, dt_s),
      derivative_(derivative_section(parameters, dt_s)) {}

double Pid::advance_integral(double error) {
  const double integrand = parameters_.integral_gain_per_s * error;
  if (parameters_.anti_windup == AntiWindup::kBackCalculation) {
    const double tracking = (output_ - unlimited_output_) / parameters_.tracking_time_constant_s;
    return integral_.step(integrand + tracking);
  }
  // Conditional integration: advance unless that drives a saturated output further out.
  const double candidate = integral_.peek(integrand);
  const double unlimited = proportional_ + candidate + derivative_.output();
  const double change = candidate - integral_.output();
  const bool deeper_above = unlimited > parameters_.output_max && change > 0.0;
  const bool deeper_below = unlimited < parameters_.output_min && change < 0.0;
  if (deeper_above || deeper_below) {
    integral_.hold();
    return integral_.output();
  }
  return integral_.step(integrand);
}

double Pid::step(double error) {
  require_finite_input(kBlock, error);
  proportional_ = parameters_.proportional_gain * error;
  const double d = derivative_.step(error);
  const double i = advance_integral(error);
  unlimited_output_ = proportional_ + i + d;
  output_ = std::clamp(unlimited_output_, parameters_.output_min, parameters_.output_max);
  saturated_ = output_ != unlimited_output_;
  return output_;
}

void Pid::reset() {
  integral_.reset(0.0);
  derivative_.reset_to_input(0.0);
  proportional_ = 0.0;
  unlimited_output_ = 0.0;
  output_ = std::clamp(0.0, parameters_.output_min, parameters_.output_max);
  saturated_ = output_ != 0.0;
}

void Pid::engage(double error, double output) {
  require_finite("Pid::engage", "error", error);
  require_finite("Pid::engage", "output", output);
  if (output < parameters_.output_min || output > parameters_.output_max) {
    std::ostringstream message;
    message.precision(9);
    message << "Pid::engage: output = " << output << " lies outside [output_min, output_max] = ["
            << parameters_.output_min << ", " << parameters_.output_max << "]";
    throw std::invalid_argument(message.str());
  }
  proportional_ = parameters_.proportional_gain * error;
  derivative_.reset_to_input(error);  // at rest on e: its output is 0
  // The trapezoid continues as if Ki e had been integrated in the last step: no half-step dip.
  integral_.reset(output - proportional_, parameters_.integral_gain_per_s * error);
  unlimited_output_ = output;
  output_ = output;
  saturated_ = false;
}

}  // namespace fedsim::control
