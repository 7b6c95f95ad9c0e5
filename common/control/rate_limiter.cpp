#include "common/control/rate_limiter.hpp"

#include <algorithm>

#include "common/control/parameter_checks.hpp"

namespace fedsim::control {
namespace {

constexpr const char* kBlock = "RateLimiter";

double checked_step(const char* parameter, double rate_per_s, double dt_s) {
  require_positive(kBlock, parameter, rate_per_s);
  require_sample_period(kBlock, dt_s);
  return rate_per_s * dt_s;
}

double checked_symmetric_rate(double rate_limit_per_s) {
  require_positive(kBlock, "rate_limit_per_s", rate_limit_per_s);
  return rate_limit_per_s;
}

}  // namespace

RateLimiter::RateLimiter(double rate_limit_per_s, double dt_s)
    : RateLimiter(checked_symmetric_rate(rate_limit_per_s), rate_limit_per_s, dt_s) {}

RateLimiter::RateLimiter(double rise_rate_per_s, double fall_rate_per_s, double dt_s)
    : rise_rate_per_s_(rise_rate_per_s),
      fall_rate_per_s_(fall_rate_per_s),
      max_rise_per_step_(checked_step("rise_rate_per_s", rise_rate_per_s, dt_s)),
      max_fall_per_step_(checked_step("fall_rate_per_s", fall_rate_per_s, dt_s)) {}

double RateLimiter::step(double u) {
  require_finite_input(kBlock, u);
  const double wanted = u - output_;
  const double allowed = std::clamp(wanted, -max_fall_per_step_, max_rise_per_step_);
  limited_ = allowed != wanted;
  output_ = limited_ ? output_ + allowed : u;  // unlimited: exactly u, no round-off drift
  return output_;
}

void RateLimiter::reset(double y) {
  require_finite("RateLimiter::reset", "output", y);
  output_ = y;
  limited_ = false;
}

}  // namespace fedsim::control
