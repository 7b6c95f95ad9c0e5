#include "common/control/lead_lag.hpp"

#include <cmath>

#include "common/control/first_order_discretisation.hpp"

namespace fedsim::control {
namespace {

DiscreteTransferFunction<1> discretise(double lead_s, double lag_s, double dt_s, double gain) {
  const ContinuousTransferFunction<1> h{{gain, gain * lead_s}, {1.0, lag_s}};
  return discretise_first_order(
      "LeadLag", {{"lead_time_constant_s", lead_s}, {"lag_time_constant_s", lag_s}}, dt_s, gain, h,
      1.0 / std::sqrt(lead_s * lag_s));
}

}  // namespace

LeadLag::LeadLag(double lead_time_constant_s, double lag_time_constant_s, double dt_s, double gain)
    : LinearBlock<1>("LeadLag",
                     discretise(lead_time_constant_s, lag_time_constant_s, dt_s, gain)),
      lead_time_constant_s_(lead_time_constant_s),
      lag_time_constant_s_(lag_time_constant_s),
      gain_(gain) {}

double LeadLag::prewarp_frequency_radps() const {
  return 1.0 / std::sqrt(lead_time_constant_s_ * lag_time_constant_s_);
}

}  // namespace fedsim::control
