// The one discretisation of the first-order blocks (FirstOrderLag, Washout, LeadLag): the checks
// of their physical parameters and the pre-warped bilinear transform of their continuous form
//   H(s) = (n0 + n1 s) / (d0 + d1 s).
#pragma once

#include <initializer_list>
#include <string_view>

#include "common/control/bilinear.hpp"

namespace fedsim::control {

/// A time constant of a first-order block, with the parameter name it came from.
struct NamedTimeConstant {
  std::string_view name;  // e.g. "time_constant_s"
  double value_s;         // tau [s]
};

/// Checks the parameters of a first-order block, in this order, so that a message names the
/// first bad one: every time constant finite and > 0, dt_s > 0, gain finite and non-zero, every
/// corner 1/tau below the Nyquist frequency pi/dt_s ("corner 1/<name>"). Then returns the
/// bilinear transform of h pre-warped at prewarp_radps (exact there: the corner of a lag or
/// washout, the geometric mean of a lead-lag's corners). Throws std::invalid_argument naming
/// the block.
DiscreteTransferFunction<1> discretise_first_order(
    std::string_view block, std::initializer_list<NamedTimeConstant> time_constants, double dt_s,
    double gain, const ContinuousTransferFunction<1>& h, double prewarp_radps);

}  // namespace fedsim::control
