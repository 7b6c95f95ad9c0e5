#include "common/control/limiter.hpp"

#include <algorithm>

#include "common/control/parameter_checks.hpp"

namespace fedsim::control {

Limiter::Limiter(double lower_limit, double upper_limit)
    : lower_limit_(lower_limit), upper_limit_(upper_limit) {
  require_limits("Limiter", "lower_limit", lower_limit, "upper_limit", upper_limit);
  output_ = std::clamp(0.0, lower_limit_, upper_limit_);
}

double Limiter::step(double u) {
  require_finite_input("Limiter", u);
  output_ = std::clamp(u, lower_limit_, upper_limit_);
  limited_ = output_ != u;
  return output_;
}

void Limiter::reset(double y) {
  require_finite("Limiter::reset", "output", y);
  require_within_limits("Limiter::reset", "output", y, lower_limit_, upper_limit_);
  output_ = y;
  limited_ = false;
}

}  // namespace fedsim::control
