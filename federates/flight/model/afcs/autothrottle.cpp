#include "flight/model/afcs/autothrottle.hpp"

#include <algorithm>

namespace fedsim::flight::afcs {

namespace {

control::PidParameters speed_pid(const AutothrottleGains& g) {
  control::PidParameters p = control::pi_parameters(
      g.speed_proportional_per_mps, g.speed_integral_per_mps_s, g.idle_throttle, 1.0);
  p.derivative_gain_s = g.speed_derivative_s;
  p.derivative_filter_time_constant_s = g.derivative_filter_s;
  return p;
}

control::PidParameters climb_pid(const AutothrottleGains& g) {
  return control::pi_parameters(g.climb_rate_proportional_per_mps,
                                g.climb_rate_integral_per_mps_s, g.idle_throttle, 1.0);
}

}  // namespace

Autothrottle::Autothrottle(const AutothrottleGains& gains, double dt_s)
    : gains_(gains),
      speed_(speed_pid(gains), dt_s),
      climb_(climb_pid(gains), dt_s),
      limiter_(gains.lever_rate_per_s, dt_s),
      retard_(gains.retard_rate_per_s, dt_s) {}

void Autothrottle::engage(double throttle) {
  const double t = std::clamp(throttle, gains_.idle_throttle, 1.0);
  limiter_.reset(t);
  retard_.reset(t);
  mode_ = ThrustMode::kNone;
}

double Autothrottle::step(ThrustMode mode, double cas_error_mps, double climb_rate_error_mps,
                          double throttle_now) {
  const double lever = limiter_.output();
  if (mode != mode_) {
    // Each controller starts from where the levers are: no step at a mode change.
    if (mode == ThrustMode::kSpeed) speed_.engage(cas_error_mps, std::clamp(lever, gains_.idle_throttle, 1.0));
    if (mode == ThrustMode::kGoAround) climb_.engage(climb_rate_error_mps, std::clamp(lever, gains_.idle_throttle, 1.0));
    retard_.reset(lever);
    mode_ = mode;
  }
  switch (mode) {
    case ThrustMode::kSpeed:
      return limiter_.step(speed_.step(cas_error_mps));
    case ThrustMode::kGoAround:
      return limiter_.step(climb_.step(climb_rate_error_mps));
    case ThrustMode::kClimb:
      return limiter_.step(gains_.climb_throttle);
    case ThrustMode::kIdle:
    case ThrustMode::kRetard: {
      const double t = retard_.step(gains_.idle_throttle);
      limiter_.reset(t);
      return t;
    }
    case ThrustMode::kArm:
    case ThrustMode::kNone:
      break;
  }
  limiter_.reset(std::clamp(throttle_now, 0.0, 1.0));
  return limiter_.output();
}

}  // namespace fedsim::flight::afcs
