#include "motion/model/jack_actuator.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>
#include <stdexcept>

#include "common/control/parameter_checks.hpp"

namespace fedsim::motion {
namespace {

constexpr const char* kBlock = "JackActuatorParameters";
constexpr double kMaxFrequencyStepProduct = 0.2;  // wa h: accuracy, well inside stability

}  // namespace

void validate(const JackActuatorParameters& p) {
  control::require_positive(kBlock, "natural_frequency_radps", p.natural_frequency_radps);
  control::require_positive_at_most(kBlock, "damping_ratio", p.damping_ratio, 5.0);
  control::require_positive(kBlock, "velocity_limit_mps", p.velocity_limit_mps);
  control::require_positive(kBlock, "acceleration_limit_mps2", p.acceleration_limit_mps2);
  control::require_positive(kBlock, "cushion_deceleration_mps2", p.cushion_deceleration_mps2);
}

JackActuator::JackActuator(const JackActuatorParameters& parameters, double min_length_m,
                           double max_length_m, double substep_s, double initial_length_m)
    : parameters_(parameters),
      min_length_m_(min_length_m),
      max_length_m_(max_length_m),
      substep_s_(substep_s),
      length_m_(initial_length_m) {
  validate(parameters_);
  control::require_positive("JackActuator", "min_length_m", min_length_m);
  control::require_positive("JackActuator", "max_length_m", max_length_m);
  if (!(min_length_m < max_length_m)) {
    throw std::invalid_argument("JackActuator: min_length_m must be below max_length_m");
  }
  control::require_sample_period("JackActuator", substep_s);
  if (parameters_.natural_frequency_radps * substep_s > kMaxFrequencyStepProduct) {
    std::ostringstream message;
    message << "JackActuator: natural_frequency_radps * substep_s = "
            << parameters_.natural_frequency_radps * substep_s << " must be at most "
            << kMaxFrequencyStepProduct << " (use a shorter sub-step)";
    throw std::invalid_argument(message.str());
  }
  reset(initial_length_m);
}

void JackActuator::reset(double length_m) {
  if (!std::isfinite(length_m) || length_m < min_length_m_ || length_m > max_length_m_) {
    throw std::invalid_argument("JackActuator: reset length outside the stroke");
  }
  length_m_ = length_m;
  velocity_mps_ = 0.0;
  acceleration_mps2_ = 0.0;
  rate_limited_ = cushioned_ = false;
  at_end_stop_ = length_m == min_length_m_ || length_m == max_length_m_;
}

// The fastest the jack may run towards the end it is heading for and still stop at it braking at
// a = cushion_deceleration: after this sub-step's travel h v the rest must suffice,
// v^2 = 2 a (d - h v), i.e. v = sqrt((a h)^2 + 2 a d) - a h (the discrete braking curve; the
// continuous v = sqrt(2 a d) would brake harder than a in the last sub-steps).
double JackActuator::cushion_speed_limit_mps(double velocity_mps) const {
  const double distance_m =
      std::max(velocity_mps > 0.0 ? max_length_m_ - length_m_ : length_m_ - min_length_m_, 0.0);
  const double a_h = parameters_.cushion_deceleration_mps2 * substep_s_;
  return std::sqrt(a_h * a_h + 2.0 * parameters_.cushion_deceleration_mps2 * distance_m) - a_h;
}

void JackActuator::step(double command_length_m) {
  if (!std::isfinite(command_length_m)) {
    throw std::invalid_argument("JackActuator: the command length is not finite");
  }
  const double wa = parameters_.natural_frequency_radps;
  // Damping taken half old, half new velocity (the 1 + zeta wa h): the discrete decay per step
  // is (1 - zeta wa h)/(1 + zeta wa h) = exp(-2 zeta wa h) to third order, so the damping is
  // that of the continuous servo (explicit damping would add zeta wa h/2 to zeta).
  const double zeta_wa_h = parameters_.damping_ratio * wa * substep_s_;
  const double demanded_mps2 = (wa * wa * (command_length_m - length_m_) -
                                2.0 * parameters_.damping_ratio * wa * velocity_mps_) /
                               (1.0 + zeta_wa_h);
  const double a_limit = parameters_.acceleration_limit_mps2;
  const double accelerated_mps2 = std::clamp(demanded_mps2, -a_limit, a_limit);
  const double v_limit = parameters_.velocity_limit_mps;
  const double unlimited_mps = velocity_mps_ + accelerated_mps2 * substep_s_;
  double velocity_mps = std::clamp(unlimited_mps, -v_limit, v_limit);
  rate_limited_ = accelerated_mps2 != demanded_mps2 || velocity_mps != unlimited_mps;

  const double cushion_mps = cushion_speed_limit_mps(velocity_mps);
  cushioned_ = std::abs(velocity_mps) > cushion_mps;
  if (cushioned_) velocity_mps = std::copysign(cushion_mps, velocity_mps);

  const double previous_velocity_mps = velocity_mps_;
  const double free_length_m = length_m_ + velocity_mps * substep_s_;
  length_m_ = std::clamp(free_length_m, min_length_m_, max_length_m_);
  at_end_stop_ =
      length_m_ != free_length_m || length_m_ == min_length_m_ || length_m_ == max_length_m_;
  if (length_m_ != free_length_m) velocity_mps = 0.0;
  velocity_mps_ = velocity_mps;
  acceleration_mps2_ = (velocity_mps_ - previous_velocity_mps) / substep_s_;
}

}  // namespace fedsim::motion
