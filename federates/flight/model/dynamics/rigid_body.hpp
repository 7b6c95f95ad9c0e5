// A rigid body moving under a ForceSource: state, clock and integrator around RigidBodyDynamics.
#pragma once

#include "flight/model/dynamics/force_source.hpp"
#include "flight/model/dynamics/rigid_body_dynamics.hpp"
#include "common/math/integrator.hpp"

#include <optional>

namespace fedsim::flight {

struct RigidBodyConfig {
  EarthModelConfig earth;
  IntegrationMethod method = IntegrationMethod::kRk4;
  /// Gain of the quaternion algebraic constraint as k h (seed eqs 3.67-3.70 need k h <= 1);
  /// unset: the largest stable gain for the integration method.
  std::optional<double> quaternion_constraint_kh;
};

/// Owns the state and advances it frame by frame. Neither step() nor outputs() allocates.
class RigidBody {
 public:
  RigidBody(const RigidBodyConfig& config, const MassProperties& mass);

  /// Starts (or restarts) a run: sets the state and clock and clears the integrator history.
  void reset(const InitialConditions& initial, double t_s = 0.0);
  /// Moves the body to a new state (reposition): clears the integrator history.
  void set_state(const RigidBodyState& state, double t_s);
  void set_mass_properties(const MassProperties& mass) { dynamics_.set_mass_properties(mass); }
  void set_integration_method(IntegrationMethod method) { integrator_.set_method(method); }

  /// Advances one frame of frame_dt seconds in `substeps` equal integration steps.
  void step(double frame_dt_s, int substeps, ForceSource& forces);

  RigidBodyState state() const { return RigidBodyDynamics::unpack(x_); }
  double time_s() const { return t_s_; }
  RigidBodyOutputs outputs() const { return dynamics_.outputs(state()); }
  RigidBodyAccelerations accelerations(const Wrench& wrench) const {
    return dynamics_.accelerations(state(), wrench);
  }
  const RigidBodyDynamics& dynamics() const { return dynamics_; }
  IntegrationMethod integration_method() const { return integrator_.method(); }

 private:
  RigidBodyDynamics dynamics_;
  Integrator<RigidBodyDynamics::kStateSize> integrator_;
  std::optional<double> quaternion_constraint_kh_;
  RigidBodyDynamics::StateVector x_;
  double t_s_ = 0.0;
};

}  // namespace fedsim::flight
