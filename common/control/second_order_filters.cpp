#include "common/control/second_order_filters.hpp"


#include "common/control/parameter_checks.hpp"

namespace fedsim::control {
namespace {

enum class Shape { kLowPass, kHighPass, kBandPass, kNotch };

// Checks the parameters and discretises n(s) / (s^2 + 2 zeta wn s + wn^2), pre-warped at wn.
DiscreteTransferFunction<2> discretise(const char* block, const char* frequency_name, Shape shape,
                                       double wn_radps, double zeta, double dt_s) {
  require_positive(block, frequency_name, wn_radps);
  if (shape == Shape::kBandPass || shape == Shape::kNotch) {
    require_positive(block, "damping_ratio", zeta);  // zeta sets the width: 0 is no filter
  } else {
    require_non_negative(block, "damping_ratio", zeta);
  }
  require_sample_period(block, dt_s);
  require_below_nyquist(block, frequency_name, wn_radps, dt_s);
  const double wn2 = wn_radps * wn_radps;
  ContinuousTransferFunction<2> h{{}, {wn2, 2.0 * zeta * wn_radps, 1.0}};
  switch (shape) {
    case Shape::kLowPass: h.numerator = {wn2, 0.0, 0.0}; break;
    case Shape::kHighPass: h.numerator = {0.0, 0.0, 1.0}; break;
    case Shape::kBandPass: h.numerator = {0.0, 2.0 * zeta * wn_radps, 0.0}; break;
    case Shape::kNotch: h.numerator = {wn2, 0.0, 1.0}; break;
  }
  return bilinear(h, prewarped_tustin_constant_per_s(dt_s, wn_radps));
}

}  // namespace

SecondOrderLowPass::SecondOrderLowPass(double natural_frequency_radps, double damping_ratio,
                                       double dt_s)
    : LinearSection<2>(discretise("SecondOrderLowPass", "natural_frequency_radps",
                                  Shape::kLowPass, natural_frequency_radps, damping_ratio, dt_s)),
      natural_frequency_radps_(natural_frequency_radps),
      damping_ratio_(damping_ratio) {}

double SecondOrderLowPass::step(double u) {
  require_finite_input("SecondOrderLowPass", u);
  return LinearSection<2>::step(u);
}

void SecondOrderLowPass::reset(double y) {
  require_finite("SecondOrderLowPass::reset", "output", y);
  reset_to_output(y);
}

void SecondOrderLowPass::reset_to_input(double u) {
  require_finite("SecondOrderLowPass::reset_to_input", "input", u);
  LinearSection<2>::reset_to_input(u);
}

SecondOrderHighPass::SecondOrderHighPass(double natural_frequency_radps, double damping_ratio,
                                         double dt_s)
    : LinearSection<2>(discretise("SecondOrderHighPass", "natural_frequency_radps",
                                  Shape::kHighPass, natural_frequency_radps, damping_ratio, dt_s)),
      natural_frequency_radps_(natural_frequency_radps),
      damping_ratio_(damping_ratio) {}

double SecondOrderHighPass::step(double u) {
  require_finite_input("SecondOrderHighPass", u);
  return LinearSection<2>::step(u);
}

void SecondOrderHighPass::reset_to_input(double u) {
  require_finite("SecondOrderHighPass::reset_to_input", "input", u);
  LinearSection<2>::reset_to_input(u);
}

BandPass::BandPass(double centre_frequency_radps, double damping_ratio, double dt_s)
    : LinearSection<2>(discretise("BandPass", "centre_frequency_radps", Shape::kBandPass,
                                  centre_frequency_radps, damping_ratio, dt_s)),
      centre_frequency_radps_(centre_frequency_radps),
      damping_ratio_(damping_ratio) {}

double BandPass::step(double u) {
  require_finite_input("BandPass", u);
  return LinearSection<2>::step(u);
}

void BandPass::reset_to_input(double u) {
  require_finite("BandPass::reset_to_input", "input", u);
  LinearSection<2>::reset_to_input(u);
}

Notch::Notch(double centre_frequency_radps, double damping_ratio, double dt_s)
    : LinearSection<2>(discretise("Notch", "centre_frequency_radps", Shape::kNotch,
                                  centre_frequency_radps, damping_ratio, dt_s)),
      centre_frequency_radps_(centre_frequency_radps),
      damping_ratio_(damping_ratio) {}

double Notch::step(double u) {
  require_finite_input("Notch", u);
  return LinearSection<2>::step(u);
}

void Notch::reset(double y) {
  require_finite("Notch::reset", "output", y);
  reset_to_output(y);
}

void Notch::reset_to_input(double u) {
  require_finite("Notch::reset_to_input", "input", u);
  LinearSection<2>::reset_to_input(u);
}

}  // namespace fedsim::control
