// Lead-lag  H(s) = K (tau1 s + 1) / (tau2 s + 1): phase lead where tau1 > tau2, lag where
// tau1 < tau2 (compensators, the turn-coordinator and stick-shaping filters).
// Input u (any unit), output y, sampled every dt_s.
//
// Discretised by the bilinear transform pre-warped at the geometric mean of the two corners,
// w_m = 1/sqrt(tau1 tau2), the frequency of the largest phase lead or lag: the discrete response
// is exact there and is H(j c tan(w dt/2)) at any w, c = w_m / tan(w_m dt/2). DC gain exactly K,
// high-frequency gain (w -> Nyquist) exactly K tau1/tau2.
//
// step(u), output(), reset_to_input(u) and coefficients() come from LinearBlock
// (linear_block.hpp).
#pragma once

#include "common/control/linear_block.hpp"

namespace fedsim::control {

class LeadLag : public LinearBlock<1> {
 public:
  /// lead_time_constant_s tau1, lag_time_constant_s tau2: both > dt_s/pi (corners below
  /// Nyquist); dt_s > 0; gain K finite, non-zero.
  LeadLag(double lead_time_constant_s, double lag_time_constant_s, double dt_s, double gain = 1.0);

  /// Steady state at output y (held input y/K).
  using LinearBlock<1>::reset;

  double lead_time_constant_s() const { return lead_time_constant_s_; }
  double lag_time_constant_s() const { return lag_time_constant_s_; }
  double gain() const { return gain_; }
  /// w_m = 1/sqrt(tau1 tau2) [rad/s], where the discretisation is exact.
  double prewarp_frequency_radps() const;

 private:
  double lead_time_constant_s_;
  double lag_time_constant_s_;
  double gain_;
};

}  // namespace fedsim::control
