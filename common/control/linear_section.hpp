// A discrete linear section of order N (1: first-order section, 2: biquad), the engine under
// every linear block. Input u (any unit), output y (the unit of u times the gain's).
//
// Transposed direct form II (Oppenheim & Schafer, Discrete-Time Signal Processing, 3rd ed.,
// section 6.4): y = b0 u + s0;  s_k = b_{k+1} u - a_{k+1} y + s_{k+1};  s_{N-1} = b_N u - a_N y.
// N state values, no allocation, copyable (value semantics).
#pragma once

#include <array>
#include <cstddef>
#include <stdexcept>

#include "common/control/bilinear.hpp"

namespace fedsim::control {

template <std::size_t N>
class LinearSection {
 public:
  /// The zero section (y = 0); replaced by assignment.
  LinearSection() = default;
  /// A section with the given coefficients, at rest (zero state, zero output).
  explicit LinearSection(const DiscreteTransferFunction<N>& h) : h_(h) {}

  /// One sample: the output for input u. The caller checks u (the blocks do).
  double step(double u) {
    const double y = h_.b[0] * u + state_[0];
    for (std::size_t k = 0; k + 1 < N; ++k) {
      state_[k] = h_.b[k + 1] * u - h_.a[k + 1] * y + state_[k + 1];
    }
    state_[N - 1] = h_.b[N] * u - h_.a[N] * y;
    output_ = y;
    return y;
  }

  double output() const { return output_; }

  /// H(z = 1) = sum b / sum a: the steady-state output per unit constant input (for a Tustin
  /// section, H(s = 0) exactly). Infinite for a section with a pole at z = 1.
  double dc_gain() const {
    double sum_b = 0.0;
    double sum_a = 0.0;
    for (std::size_t i = 0; i <= N; ++i) {
      sum_b += h_.b[i];
      sum_a += h_.a[i];
    }
    return sum_b / sum_a;
  }

  /// The steady state under the constant input u: the output is dc_gain() u and stays there
  /// while u is held (no transient). Needs a section without a pole at z = 1.
  void reset_to_input(double u) {
    const double y = dc_gain() * u;
    if (!std::isfinite(y)) {
      throw std::logic_error("LinearSection::reset_to_input: no steady state (pole at z = 1)");
    }
    double next = 0.0;
    for (std::size_t k = N; k-- > 0;) {
      state_[k] = h_.b[k + 1] * u - h_.a[k + 1] * y + next;
      next = state_[k];
    }
    output_ = y;
  }

  /// The steady state whose output is y (the held input is y / dc_gain()). Needs a finite,
  /// non-zero DC gain: the blocks that expose it are built so.
  void reset_to_output(double y) {
    const double gain = dc_gain();
    if (gain == 0.0 || !std::isfinite(gain)) {
      throw std::logic_error("LinearSection::reset_to_output: DC gain is zero or infinite");
    }
    reset_to_input(y / gain);
    output_ = y;
  }

  const DiscreteTransferFunction<N>& coefficients() const { return h_; }

 private:
  DiscreteTransferFunction<N> h_{};
  std::array<double, N> state_{};
  double output_ = 0.0;
};

}  // namespace fedsim::control
