// Second-order filters on the denominator  s^2 + 2 zeta wn s + wn^2  (natural frequency wn
// [rad/s], damping ratio zeta [-]), four small siblings that share one discretisation:
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
#pragma once

#include "common/control/linear_section.hpp"

namespace fedsim::control {

class SecondOrderLowPass : private LinearSection<2> {
 public:
  /// natural_frequency_radps: 0 < wn < pi/dt_s; damping_ratio: zeta >= 0; dt_s > 0.
  SecondOrderLowPass(double natural_frequency_radps, double damping_ratio, double dt_s);

  double step(double u);
  using LinearSection<2>::output;
  /// Steady state at output y (held input y).
  void reset(double y);
  void reset_to_input(double u);

  double natural_frequency_radps() const { return natural_frequency_radps_; }
  double damping_ratio() const { return damping_ratio_; }
  using LinearSection<2>::coefficients;

 private:
  double natural_frequency_radps_;
  double damping_ratio_;
};

class SecondOrderHighPass : private LinearSection<2> {
 public:
  /// natural_frequency_radps: 0 < wn < pi/dt_s; damping_ratio: zeta >= 0; dt_s > 0.
  SecondOrderHighPass(double natural_frequency_radps, double damping_ratio, double dt_s);

  double step(double u);
  using LinearSection<2>::output;
  /// Steady state under the held input u: output 0 (a high-pass has no other steady state).
  void reset_to_input(double u);

  double natural_frequency_radps() const { return natural_frequency_radps_; }
  double damping_ratio() const { return damping_ratio_; }
  using LinearSection<2>::coefficients;

 private:
  double natural_frequency_radps_;
  double damping_ratio_;
};

class BandPass : private LinearSection<2> {
 public:
  /// centre_frequency_radps: 0 < wn < pi/dt_s; damping_ratio: zeta > 0 (the -3 dB width is
  /// 2 zeta wn); dt_s > 0.
  BandPass(double centre_frequency_radps, double damping_ratio, double dt_s);

  double step(double u);
  using LinearSection<2>::output;
  /// Steady state under the held input u: output 0.
  void reset_to_input(double u);

  double centre_frequency_radps() const { return centre_frequency_radps_; }
  double damping_ratio() const { return damping_ratio_; }
  using LinearSection<2>::coefficients;

 private:
  double centre_frequency_radps_;
  double damping_ratio_;
};

class Notch : private LinearSection<2> {
 public:
  /// centre_frequency_radps: 0 < wn < pi/dt_s; damping_ratio: zeta > 0 (the -3 dB width is
  /// 2 zeta wn); dt_s > 0.
  Notch(double centre_frequency_radps, double damping_ratio, double dt_s);

  double step(double u);
  using LinearSection<2>::output;
  /// Steady state at output y (held input y).
  void reset(double y);
  void reset_to_input(double u);

  double centre_frequency_radps() const { return centre_frequency_radps_; }
  double damping_ratio() const { return damping_ratio_; }
  using LinearSection<2>::coefficients;

 private:
  double centre_frequency_radps_;
  double damping_ratio_;
};

}  // namespace fedsim::control
