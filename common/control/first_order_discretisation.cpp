#include "common/control/first_order_discretisation.hpp"

#include <string>

#include "common/control/parameter_checks.hpp"

namespace fedsim::control {

DiscreteTransferFunction<1> discretise_first_order(
    std::string_view block, std::initializer_list<NamedTimeConstant> time_constants, double dt_s,
    double gain, const ContinuousTransferFunction<1>& h, double prewarp_radps) {
  for (const NamedTimeConstant& tau : time_constants) {
    require_positive(block, tau.name, tau.value_s);
  }
  require_sample_period(block, dt_s);
  require_non_zero(block, "gain", gain);
  for (const NamedTimeConstant& tau : time_constants) {
    require_below_nyquist(block, std::string("corner 1/").append(tau.name), 1.0 / tau.value_s,
                          dt_s);
  }
  return bilinear(h, prewarped_tustin_constant_per_s(dt_s, prewarp_radps));
}

}  // namespace fedsim::control
