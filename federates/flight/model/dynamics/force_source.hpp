// Interface of whatever produces the forces and moments on a rigid body (aircraft, test bodies).
#pragma once

#include "flight/model/dynamics/rigid_body_state.hpp"

namespace fedsim::flight {

/// Called by the integrator at every derivative evaluation (4 times per RK4 step, once per
/// Adams-Bashforth step) with the trial state and time; must not allocate.
class ForceSource {
 public:
  virtual ~ForceSource() = default;
  /// Body-axis force (N) and moment about the CG (N m), excluding gravity.
  virtual Wrench forces(const RigidBodyState& state, double t_s) = 0;
};

}  // namespace fedsim::flight
