// State of a rigid body and the wrench (force, moment) acting on it.
#pragma once

#include <Eigen/Core>
#include <Eigen/Geometry>

namespace fedsim::flight {

/// Rigid-body state. The reference frame depends on the earth model:
///   flat earth  : NED axes fixed at the scenario origin (lat0, lon0, h = 0), treated as inertial;
///   WGS-84 earth: ECEF axes (rotating with the earth).
/// Positions are always double precision (seed 3.5.7: float is not enough for lat/lon).
struct RigidBodyState {
  Eigen::Vector3d position_m = Eigen::Vector3d::Zero();    // CG in the reference frame
  Eigen::Vector3d velocity_mps = Eigen::Vector3d::Zero();  // CG velocity relative to the earth,
                                                           // reference-frame axes
  Eigen::Quaterniond attitude = Eigen::Quaterniond::Identity();  // body -> reference frame:
                                                                 // v_ref = attitude * v_body
  Eigen::Vector3d omega_body_radps = Eigen::Vector3d::Zero();  // body rate relative to inertial space
};

/// Forces and moments on the body, body axes, about the CG, gravity excluded (the earth model
/// adds it). The angular momentum of spinning rotors (engines, propellers) is optional; it adds
/// the gyroscopic moment -omega x h_rotor (seed eqs 3.110-3.112).
struct Wrench {
  Eigen::Vector3d force_body_n = Eigen::Vector3d::Zero();
  Eigen::Vector3d moment_body_nm = Eigen::Vector3d::Zero();
  Eigen::Vector3d rotor_momentum_body_kgm2ps = Eigen::Vector3d::Zero();
};

}  // namespace fedsim::flight
