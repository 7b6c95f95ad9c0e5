#include "common/control/integrator.hpp"

#include <algorithm>

#include "common/control/bilinear.hpp"
#include "common/control/parameter_checks.hpp"

namespace fedsim::control {
namespace {

constexpr const char* kBlock = "Integrator";

// K T/2 from the bilinear transform of K/s (b = {K T/2, K T/2}, a = {1, -1}).
double half_step_gain(double gain_per_s, double dt_s) {
  require_non_zero(kBlock, "gain_per_s", gain_per_s);
  require_sample_period(kBlock, dt_s);
  const ContinuousTransferFunction<1> h{{gain_per_s, 0.0}, {0.0, 1.0}};
  return bilinear(h, tustin_constant_per_s(dt_s)).b[0];
}

}  // namespace

Integrator::Integrator(double gain_per_s, double dt_s, double lower_limit, double upper_limit)
    : gain_per_s_(gain_per_s),
      half_step_gain_(half_step_gain(gain_per_s, dt_s)),
      lower_limit_(lower_limit),
      upper_limit_(upper_limit) {
  require_limits(kBlock, "lower_limit", lower_limit, "upper_limit", upper_limit);
  output_ = std::clamp(0.0, lower_limit_, upper_limit_);
}

double Integrator::unclamped(double u) const {
  return output_ + half_step_gain_ * (u + previous_input_);
}

double Integrator::peek(double u) const {
  return std::clamp(unclamped(u), lower_limit_, upper_limit_);
}

double Integrator::step(double u) {
  require_finite_input(kBlock, u);
  const double candidate = unclamped(u);
  output_ = std::clamp(candidate, lower_limit_, upper_limit_);
  limited_ = output_ != candidate;
  previous_input_ = limited_ ? 0.0 : u;
  return output_;
}

void Integrator::hold() {
  previous_input_ = 0.0;
  limited_ = false;
}

void Integrator::reset(double y, double previous_input) {
  require_finite("Integrator::reset", "output", y);
  require_finite("Integrator::reset", "previous_input", previous_input);
  require_within_limits("Integrator::reset", "output", y, lower_limit_, upper_limit_);
  output_ = y;
  previous_input_ = previous_input;
  limited_ = false;
}

}  // namespace fedsim::control
