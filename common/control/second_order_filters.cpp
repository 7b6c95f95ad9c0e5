#include "common/control/second_order_filters.hpp"

#include "common/control/parameter_checks.hpp"

namespace fedsim::control {
namespace {

using enum SecondOrderShape;

constexpr const char* block_name(SecondOrderShape shape) {
  switch (shape) {
    case kLowPass: return "SecondOrderLowPass";
    case kHighPass: return "SecondOrderHighPass";
    case kBandPass: return "BandPass";
    case kNotch: return "Notch";
  }
  return "SecondOrderFilter";
}

constexpr const char* frequency_name(SecondOrderShape shape) {
  return shape == kBandPass || shape == kNotch ? "centre_frequency_radps"
                                               : "natural_frequency_radps";
}

// Checks the parameters and discretises n(s) / (s^2 + 2 zeta wn s + wn^2), pre-warped at wn.
DiscreteTransferFunction<2> discretise(SecondOrderShape shape, double wn_radps, double zeta,
                                       double dt_s) {
  const char* block = block_name(shape);
  require_positive(block, frequency_name(shape), wn_radps);
  if (shape == kBandPass || shape == kNotch) {
    require_positive(block, "damping_ratio", zeta);  // zeta sets the width: 0 is no filter
  } else {
    require_non_negative(block, "damping_ratio", zeta);
  }
  require_sample_period(block, dt_s);
  require_below_nyquist(block, frequency_name(shape), wn_radps, dt_s);
  const double wn2 = wn_radps * wn_radps;
  ContinuousTransferFunction<2> h{{}, {wn2, 2.0 * zeta * wn_radps, 1.0}};
  switch (shape) {
    case kLowPass: h.numerator = {wn2, 0.0, 0.0}; break;
    case kHighPass: h.numerator = {0.0, 0.0, 1.0}; break;
    case kBandPass: h.numerator = {0.0, 2.0 * zeta * wn_radps, 0.0}; break;
    case kNotch: h.numerator = {wn2, 0.0, 1.0}; break;
  }
  return bilinear(h, prewarped_tustin_constant_per_s(dt_s, wn_radps));
}

}  // namespace

template <SecondOrderShape S>
SecondOrderFilter<S>::SecondOrderFilter(double frequency_radps, double damping_ratio, double dt_s)
    : LinearBlock<2>(block_name(S), discretise(S, frequency_radps, damping_ratio, dt_s)),
      frequency_radps_(frequency_radps),
      damping_ratio_(damping_ratio) {}

template class SecondOrderFilter<SecondOrderShape::kLowPass>;
template class SecondOrderFilter<SecondOrderShape::kHighPass>;
template class SecondOrderFilter<SecondOrderShape::kBandPass>;
template class SecondOrderFilter<SecondOrderShape::kNotch>;

}  // namespace fedsim::control
