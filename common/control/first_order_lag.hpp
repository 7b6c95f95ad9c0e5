// First-order lag  H(s) = K / (tau s + 1)  (a sensor or actuator lag, a smoothing filter).
// Input u (any unit), output y = K-scaled u, sampled every dt_s.
//
// Discretised by the bilinear transform pre-warped at the corner 1/tau: the discrete gain and
// phase at w = 1/tau are exactly K/sqrt(2) and -45 degrees whatever the ratio of tau to dt_s,
// and at any w the response is H(j c tan(w dt/2)), c = (1/tau)/tan(dt/(2 tau)). The DC gain is
// exactly K. For tau >> dt_s, c -> 2/dt_s (plain Tustin) to within (dt/tau)^2/12.
//
// step(u), output(), reset_to_input(u) (steady under the held input u, output K u) and
// coefficients() come from LinearBlock (linear_block.hpp), time_constant_s() and gain() from
// FirstOrderBlock (first_order_block.hpp).
#pragma once

#include "common/control/first_order_block.hpp"

namespace fedsim::control {

class FirstOrderLag : public FirstOrderBlock {
 public:
  /// time_constant_s: tau > dt_s/pi (corner below Nyquist); dt_s > 0; gain: K finite, non-zero.
  FirstOrderLag(double time_constant_s, double dt_s, double gain = 1.0);

  /// Steady state at output y (the held input y/K): no transient follows.
  using FirstOrderBlock::reset;
};

}  // namespace fedsim::control
