// What the two first-order blocks with one time constant tau and a gain K share: the lag
// K/(tau s + 1) (first_order_lag.hpp) and the washout K tau s/(tau s + 1) (washout.hpp). Both
// are checked and discretised alike (first_order_discretisation.hpp: tau > dt_s/pi, dt_s > 0,
// K finite and non-zero; pre-warped at the corner 1/tau) and differ only in the numerator.
#pragma once

#include <array>

#include "common/control/first_order_discretisation.hpp"
#include "common/control/linear_block.hpp"

namespace fedsim::control {

class FirstOrderBlock : public LinearBlock<1> {
 public:
  double time_constant_s() const { return time_constant_s_; }
  double gain() const { return gain_; }

 protected:
  /// numerator: (n0, n1) of H(s) = (n0 + n1 s) / (1 + tau s), tau = time_constant_s.
  FirstOrderBlock(const char* block, double time_constant_s, double dt_s, double gain,
                  const std::array<double, 2>& numerator)
      : LinearBlock<1>(block, discretise_first_order(block, {{"time_constant_s", time_constant_s}},
                                                     dt_s, gain, {numerator, {1.0, time_constant_s}},
                                                     1.0 / time_constant_s)),
        time_constant_s_(time_constant_s),
        gain_(gain) {}

 private:
  double time_constant_s_;
  double gain_;
};

}  // namespace fedsim::control
