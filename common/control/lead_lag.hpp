// Lead-lag  H(s) = K (tau1 s + 1) / (tau2 s + 1): phase lead where tau1 > tau2, lag where
// tau1 < tau2 (compensators, the turn-coordinator and stick-shaping filters).
// Input u (any unit), output y, sampled every dt_s.
//
// Discretised by the bilinear transform pre-warped at the geometric mean of the two corners,
// w_m = 1/sqrt(tau1 tau2), the frequency of the largest phase lead or lag: the discrete response
// is exact there and is H(j c tan(w dt/2)) at any w, c = w_m / tan(w_m dt/2). DC gain exactly K,
// high-frequency gain (w -> Nyquist) exactly K tau1/tau2.
#pragma once

#include "common/control/linear_section.hpp"

namespace fedsim::control {

class LeadLag : private LinearSection<1> {
 public:
  /// lead_time_constant_s tau1, lag_time_constant_s tau2: both > dt_s/pi (corners below
  /// Nyquist); dt_s > 0; gain K finite, non-zero.
  LeadLag(double lead_time_constant_s, double lag_time_constant_s, double dt_s, double gain = 1.0);

  double step(double u);
  using LinearSection<1>::output;
  /// Steady state at output y (held input y/K).
  void reset(double y);
  /// Steady state under the held input u.
  void reset_to_input(double u);

  double lead_time_constant_s() const { return lead_time_constant_s_; }
  double lag_time_constant_s() const { return lag_time_constant_s_; }
  double gain() const { return gain_; }
  /// w_m = 1/sqrt(tau1 tau2) [rad/s], where the discretisation is exact.
  double prewarp_frequency_radps() const;
  using LinearSection<1>::coefficients;

 private:
  double lead_time_constant_s_;
  double lag_time_constant_s_;
  double gain_;
};

}  // namespace fedsim::control
