// Second-order filters on the denominator  s^2 + 2 zeta wn s + wn^2  (natural frequency wn
// [rad/s], damping ratio zeta [-]), four siblings of one class template that differ only in the
// numerator:
//   SecondOrderLowPass   wn^2 / (...)            DC gain 1 (sensor and actuator dynamics, stick
//                                                 and control-loading models)
//   SecondOrderHighPass  s^2 / (...)             DC gain 0 (translational motion-cueing washout)
//   BandPass             2 zeta wn s / (...)     gain 1 at wn, 0 at DC and Nyquist
//   Notch                (s^2 + wn^2) / (...)    gain 0 at wn, 1 at DC and Nyquist (structural
//                                                 mode filters); -3 dB width 2 zeta wn
// Input u (any unit), output y, sampled every dt_s.
//
// Each is discretised by the bilinear transform pre-warped at wn: the discrete response at wn is
// exactly the continuous one (the low-pass's -90 degrees and 1/(2 zeta), the notch's zero, the
// band-pass's unit peak), whatever wn is against Nyquist; at any w it is H(j c tan(w dt/2)),
// c = wn / tan(wn dt/2). Stable for zeta > 0; zeta = 0 (low- and high-pass only) gives poles on
// the unit circle at wn exactly (an undamped oscillator).
//
// step(u), output(), reset_to_input(u) and coefficients() come from LinearBlock
// (linear_block.hpp); reset(y) exists for the low-pass and the notch (DC gain 1) only, the
// frequency is natural_frequency_radps() for the low- and high-pass, centre_frequency_radps()
// for the band-pass and the notch.
#pragma once

#include "common/control/linear_block.hpp"

namespace fedsim::control {

enum class SecondOrderShape { kLowPass, kHighPass, kBandPass, kNotch };

template <SecondOrderShape S>
class SecondOrderFilter : public LinearBlock<2> {
  // The band-pass and notch are set by a centre and a width (zeta > 0); the others by wn.
  static constexpr bool kBand = S == SecondOrderShape::kBandPass || S == SecondOrderShape::kNotch;
  static constexpr bool kUnitDcGain = S == SecondOrderShape::kLowPass || S == SecondOrderShape::kNotch;

 public:
  /// frequency_radps: wn (the natural frequency, or the band-pass's and notch's centre),
  /// 0 < wn < pi/dt_s; damping_ratio: zeta >= 0 (> 0 for the band-pass and notch, whose -3 dB
  /// width is 2 zeta wn); dt_s > 0.
  SecondOrderFilter(double frequency_radps, double damping_ratio, double dt_s);

  /// Steady state at output y (held input y).
  void reset(double y)
    requires kUnitDcGain
  {
    LinearBlock<2>::reset(y);
  }

  double natural_frequency_radps() const
    requires(!kBand)
  {
    return frequency_radps_;
  }
  double centre_frequency_radps() const
    requires kBand
  {
    return frequency_radps_;
  }
  double damping_ratio() const { return damping_ratio_; }

 private:
  double frequency_radps_;
  double damping_ratio_;
};

using SecondOrderLowPass = SecondOrderFilter<SecondOrderShape::kLowPass>;
using SecondOrderHighPass = SecondOrderFilter<SecondOrderShape::kHighPass>;
using BandPass = SecondOrderFilter<SecondOrderShape::kBandPass>;
using Notch = SecondOrderFilter<SecondOrderShape::kNotch>;

extern template class SecondOrderFilter<SecondOrderShape::kLowPass>;
extern template class SecondOrderFilter<SecondOrderShape::kHighPass>;
extern template class SecondOrderFilter<SecondOrderShape::kBandPass>;
extern template class SecondOrderFilter<SecondOrderShape::kNotch>;

}  // namespace fedsim::control
