// The checked interface every linear block of this library (FirstOrderLag, LeadLag, Washout and
// the second-order filters) offers over its LinearSection<N>: step() rejects a non-finite input
// before it can poison the state, the resets reject a non-finite argument, and errors name the
// block ("FirstOrderLag: input = nan must be finite", "Notch::reset: output = inf ...").
// Input u (any unit), output y (the unit of u times the block's gain), sampled every dt_s.
//
// A block derives from LinearBlock<N>, passes its name and its discretised coefficients, and
// makes reset(y) public (`using LinearBlock<N>::reset;`) only when its DC gain is finite and
// non-zero: the washout, high-pass and band-pass have no steady state at a non-zero output.
// No allocation in step() or the resets (unless they throw); value semantics.
#pragma once

#include <cstddef>

#include "common/control/linear_section.hpp"
#include "common/control/parameter_checks.hpp"

namespace fedsim::control {

template <std::size_t N>
class LinearBlock {
 public:
  /// The output for input u (finite, else std::invalid_argument with the state untouched).
  double step(double u) {
    require_finite_input(block_, u);
    return section_.step(u);
  }
  /// The last output.
  double output() const { return section_.output(); }
  /// Steady state under the held input u (finite): output dc_gain u, no transient while u is
  /// held (output 0 for a block without DC gain).
  void reset_to_input(double u) {
    require_finite_argument(block_, "reset_to_input", "input", u);
    section_.reset_to_input(u);
  }
  /// The discrete coefficients (b, a) the block runs.
  const DiscreteTransferFunction<N>& coefficients() const { return section_.coefficients(); }

 protected:
  /// block: the class name for messages (a string literal); h: the checked, discretised block.
  LinearBlock(const char* block, const DiscreteTransferFunction<N>& h)
      : block_(block), section_(h) {}

  /// Steady state at output y (finite; the held input is y / dc_gain): no transient follows.
  void reset(double y) {
    require_finite_argument(block_, "reset", "output", y);
    section_.reset_to_output(y);
  }

 private:
  const char* block_;
  LinearSection<N> section_;
};

}  // namespace fedsim::control
