// Washout (first-order high-pass)  H(s) = K tau s / (tau s + 1): passes changes, removes a
// steady input with time constant tau (yaw-damper washout, rotational motion-cueing washout).
// Input u (any unit), output y, sampled every dt_s.
//
// Discretised by the bilinear transform pre-warped at the corner 1/tau (exact gain K/sqrt(2)
// and phase +45 degrees there; H(j c tan(w dt/2)) at any w, c = (1/tau)/tan(dt/(2 tau))).
// The DC gain is exactly 0, so the block has no steady state at a non-zero output: it is reset
// to a held input instead (reset_to_input), after which its output is 0 and stays 0.
//
// step(u), output(), reset_to_input(u) and coefficients() come from LinearBlock
// (linear_block.hpp), time_constant_s() and gain() from FirstOrderBlock (first_order_block.hpp).
#pragma once

#include "common/control/first_order_block.hpp"

namespace fedsim::control {

class Washout : public FirstOrderBlock {
 public:
  /// time_constant_s: tau > dt_s/pi (corner below Nyquist); dt_s > 0; gain K finite, non-zero.
  Washout(double time_constant_s, double dt_s, double gain = 1.0);
};

}  // namespace fedsim::control
