#include "common/control/first_order_lag.hpp"

#include "common/control/parameter_checks.hpp"

namespace fedsim::control {
namespace {

constexpr const char* kBlock = "FirstOrderLag";

DiscreteTransferFunction<1> discretise(double time_constant_s, double dt_s, double gain) {
  require_positive(kBlock, "time_constant_s", time_constant_s);
  require_sample_period(kBlock, dt_s);
  require_non_zero(kBlock, "gain", gain);
  const double corner_radps = 1.0 / time_constant_s;
  require_below_nyquist(kBlock, "corner 1/time_constant_s", corner_radps, dt_s);
  const ContinuousTransferFunction<1> h{{gain, 0.0}, {1.0, time_constant_s}};
  return bilinear(h, prewarped_tustin_constant_per_s(dt_s, corner_radps));
}

}  // namespace

FirstOrderLag::FirstOrderLag(double time_constant_s, double dt_s, double gain)
    : LinearSection<1>(discretise(time_constant_s, dt_s, gain)),
      time_constant_s_(time_constant_s),
      gain_(gain) {}

double FirstOrderLag::step(double u) {
  require_finite_input(kBlock, u);
  return LinearSection<1>::step(u);
}

void FirstOrderLag::reset(double y) {
  require_finite("FirstOrderLag::reset", "output", y);
  reset_to_output(y);
}

void FirstOrderLag::reset_to_input(double u) {
  require_finite("FirstOrderLag::reset_to_input", "input", u);
  LinearSection<1>::reset_to_input(u);
}

}  // namespace fedsim::control
