// Six-degree-of-freedom rigid-body equations of motion.
#include "flight/model/dynamics/rigid_body_dynamics.hpp"

#include <Eigen/Geometry>
#include <Eigen/LU>

namespace fedsim::flight {

RigidBodyDynamics::RigidBodyDynamics(EarthModel earth, const MassProperties& mass)
    : earth_(earth) {
  set_mass_properties(mass);
}

void RigidBodyDynamics::set_mass_properties(const MassProperties& mass) {
  mass.validate();
  mass_ = mass;
  inverse_inertia_ = mass_.inertia_kgm2.inverse();
}

Eigen::Vector3d RigidBodyDynamics::angular_acceleration(const Eigen::Vector3d& omega_body,
                                                        const Wrench& wrench) const {
  // Euler's equation with the full tensor and rotor momentum: the vector form of eqs
  // 3.104-3.106 plus the gyroscopic terms of 3.110-3.112 (omega x h: q hz - r hy,
  // r hx - p hz, p hy - q hx; the book's printed 3.111-3.112 swap two subscripts).
  const Eigen::Vector3d momentum = mass_.inertia_kgm2 * omega_body + wrench.rotor_momentum_body_kgm2ps;
  return inverse_inertia_ * (wrench.moment_body_nm - omega_body.cross(momentum));
}

RigidBodyDynamics::StateVector RigidBodyDynamics::derivative(const StateVector& x,
                                                             const Wrench& wrench,
                                                             double quaternion_correction_per_s) const {
  const Eigen::Vector3d position = x.segment<3>(0);
  const Eigen::Vector3d velocity = x.segment<3>(3);
  const Eigen::Vector4d quaternion = x.segment<4>(6);
  const Eigen::Vector3d omega_body = x.segment<3>(10);
  const Eigen::Matrix3d ref_from_body = dcm_from_quaternion(from_e0123(quaternion));

  StateVector dx;
  dx.segment<3>(0) = velocity;
  dx.segment<3>(3) = ref_from_body * (wrench.force_body_n / mass_.mass_kg) +
                     earth_.free_fall_acceleration(position, velocity);
  // Attitude is relative to the reference frame, which itself turns at W (zero if flat).
  const Eigen::Vector3d omega_relative_body =
      omega_body - ref_from_body.transpose() * earth_.frame_rate_radps();
  dx.segment<4>(6) = quaternion_rate(quaternion, omega_relative_body, 0.0) +
                     quaternion_correction_per_s * quaternion;
  dx.segment<3>(10) = angular_acceleration(omega_body, wrench);
  return dx;
}

double RigidBodyDynamics::quaternion_correction_per_s(const StateVector& x, double constraint_kh,
                                                      double step_s) {
  return constraint_kh / step_s * (1.0 - x.segment<4>(6).squaredNorm());
}

RigidBodyDynamics::StateVector RigidBodyDynamics::pack(const RigidBodyState& state) {
  StateVector x;
  x << state.position_m, state.velocity_mps, to_e0123(state.attitude), state.omega_body_radps;
  return x;
}

RigidBodyState RigidBodyDynamics::unpack(const StateVector& x) {
  RigidBodyState state;
  state.position_m = x.segment<3>(0);
  state.velocity_mps = x.segment<3>(3);
  state.attitude = from_e0123(x.segment<4>(6));
  state.omega_body_radps = x.segment<3>(10);
  return state;
}

RigidBodyState RigidBodyDynamics::initial_state(const InitialConditions& initial) const {
  RigidBodyState state;
  state.position_m = earth_.position_from_geodetic(initial.position);
  const Eigen::Matrix3d ned_from_ref = earth_.ned_from_reference(initial.position);
  state.velocity_mps = ned_from_ref.transpose() * initial.velocity_ned_mps;
  const Eigen::Matrix3d ref_from_body = ned_from_ref.transpose() * dcm_from_euler(initial.attitude);
  state.attitude = Eigen::Quaterniond(ref_from_body).normalized();
  state.omega_body_radps = initial.omega_body_radps;
  if (initial.omega_relative_to_earth) {
    state.omega_body_radps += ref_from_body.transpose() * earth_.frame_rate_radps();
  }
  return state;
}

RigidBodyOutputs RigidBodyDynamics::outputs(const RigidBodyState& state) const {
  RigidBodyOutputs out;
  out.geodetic = earth_.geodetic(state.position_m);
  out.position_ecef_m = earth_.ecef(state.position_m);
  const Eigen::Matrix3d ned_from_ref = earth_.ned_from_reference(out.geodetic);
  const Eigen::Matrix3d ref_from_body = dcm_from_quaternion(state.attitude);
  out.ned_from_body = ned_from_ref * ref_from_body;
  out.velocity_ned_mps = ned_from_ref * state.velocity_mps;
  out.velocity_body_mps = ref_from_body.transpose() * state.velocity_mps;
  out.euler = euler_from_dcm(out.ned_from_body);
  out.omega_body_radps = state.omega_body_radps;
  out.omega_body_wrt_earth_radps =
      state.omega_body_radps - ref_from_body.transpose() * earth_.frame_rate_radps();
  out.gravitation_ned_mps2 = ned_from_ref * earth_.gravitation(state.position_m);
  return out;
}

RigidBodyAccelerations RigidBodyDynamics::accelerations(const RigidBodyState& state,
                                                        const Wrench& wrench) const {
  RigidBodyAccelerations acc;
  const Eigen::Matrix3d ref_from_body = dcm_from_quaternion(state.attitude);
  acc.specific_force_body_mps2 = wrench.force_body_n / mass_.mass_kg;
  acc.acceleration_body_mps2 =
      acc.specific_force_body_mps2 +
      ref_from_body.transpose() *
          earth_.free_fall_acceleration(state.position_m, state.velocity_mps);
  acc.omega_dot_body_radps2 = angular_acceleration(state.omega_body_radps, wrench);
  return acc;
}

Eigen::Vector3d RigidBodyDynamics::specific_force_at_body(const RigidBodyAccelerations& accelerations,
                                                       const Eigen::Vector3d& omega_body_radps,
                                                       const Eigen::Vector3d& point_from_cg_body_m) {
  return accelerations.specific_force_body_mps2 +
         accelerations.omega_dot_body_radps2.cross(point_from_cg_body_m) +
         omega_body_radps.cross(omega_body_radps.cross(point_from_cg_body_m));
}

double RigidBodyDynamics::stable_quaternion_constraint_kh(IntegrationMethod method) {
  switch (method) {
    case IntegrationMethod::kEuler:
    case IntegrationMethod::kRk4:
      return 0.5;
    case IntegrationMethod::kAb2:
      return 0.25;
    case IntegrationMethod::kAb3:
    case IntegrationMethod::kAb4:
      return 0.1;
  }
  return 0.1;
}

}  // namespace fedsim::flight
