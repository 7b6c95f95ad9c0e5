#include "common/control/lead_lag.hpp"

#include <cmath>

#include "common/control/parameter_checks.hpp"

namespace fedsim::control {
namespace {

constexpr const char* kBlock = "LeadLag";

DiscreteTransferFunction<1> discretise(double lead_s, double lag_s, double dt_s, double gain) {
  require_positive(kBlock, "lead_time_constant_s", lead_s);
  require_positive(kBlock, "lag_time_constant_s", lag_s);
  require_sample_period(kBlock, dt_s);
  require_non_zero(kBlock, "gain", gain);
  require_below_nyquist(kBlock, "corner 1/lead_time_constant_s", 1.0 / lead_s, dt_s);
  require_below_nyquist(kBlock, "corner 1/lag_time_constant_s", 1.0 / lag_s, dt_s);
  const double prewarp_radps = 1.0 / std::sqrt(lead_s * lag_s);
  const ContinuousTransferFunction<1> h{{gain, gain * lead_s}, {1.0, lag_s}};
  return bilinear(h, prewarped_tustin_constant_per_s(dt_s, prewarp_radps));
}

}  // namespace

LeadLag::LeadLag(double lead_time_constant_s, double lag_time_constant_s, double dt_s, double gain)
    : LinearSection<1>(discretise(lead_time_constant_s, lag_time_constant_s, dt_s, gain)),
      lead_time_constant_s_(lead_time_constant_s),
      lag_time_constant_s_(lag_time_constant_s),
      gain_(gain) {}

double LeadLag::step(double u) {
  require_finite_input(kBlock, u);
  return LinearSection<1>::step(u);
}

void LeadLag::reset(double y) {
  require_finite("LeadLag::reset", "output", y);
  reset_to_output(y);
}

void LeadLag::reset_to_input(double u) {
  require_finite("LeadLag::reset_to_input", "input", u);
  LinearSection<1>::reset_to_input(u);
}

double LeadLag::prewarp_frequency_radps() const {
  return 1.0 / std::sqrt(lead_time_constant_s_ * lag_time_constant_s_);
}

}  // namespace fedsim::control
