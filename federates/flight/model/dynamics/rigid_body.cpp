// A rigid body moving under a ForceSource.
#include "flight/model/dynamics/rigid_body.hpp"

#include <stdexcept>

namespace fedsim::flight {

RigidBody::RigidBody(const RigidBodyConfig& config, const MassProperties& mass)
    : dynamics_(EarthModel(config.earth), mass),
      integrator_(config.method),
      quaternion_constraint_kh_(config.quaternion_constraint_kh),
      x_(RigidBodyDynamics::pack(RigidBodyState{})) {
  if (quaternion_constraint_kh_ &&
      !(*quaternion_constraint_kh_ >= 0.0 && *quaternion_constraint_kh_ <= 1.0)) {
    throw std::invalid_argument("rigid body: quaternion constraint k h must be in [0, 1]");
  }
}

void RigidBody::reset(const InitialConditions& initial, double t_s) {
  set_state(dynamics_.initial_state(initial), t_s);
}

void RigidBody::set_state(const RigidBodyState& state, double t_s) {
  x_ = RigidBodyDynamics::pack(state);
  t_s_ = t_s;
  integrator_.restart();
}

void RigidBody::step(double frame_dt_s, int substeps, ForceSource& forces) {
  if (substeps < 1) substeps = 1;
  const double h = frame_dt_s / static_cast<double>(substeps);
  const double kh = quaternion_constraint_kh_.value_or(
      RigidBodyDynamics::stable_quaternion_constraint_kh(integrator_.method()));
  double correction = 0.0;
  const auto derivative = [&](double t, const RigidBodyDynamics::StateVector& x) {
    const Wrench wrench = forces.forces(RigidBodyDynamics::unpack(x), t);
    return dynamics_.derivative(x, wrench, correction);
  };
  for (int i = 0; i < substeps; ++i) {
    correction = RigidBodyDynamics::quaternion_correction_per_s(x_, kh, h);
    integrator_.step(t_s_ + h * static_cast<double>(i), h, x_, derivative);
  }
  t_s_ += frame_dt_s;
}

}  // namespace fedsim::flight
