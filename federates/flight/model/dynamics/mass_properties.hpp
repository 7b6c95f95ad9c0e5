// Mass and inertia tensor of a rigid body about its centre of gravity, body axes.
#pragma once

#include <Eigen/Core>

namespace fedsim::flight {

/// The inertia tensor is stored as the full symmetric matrix
///   [ Ixx  -Ixy  -Ixz ]
///   [-Ixy   Iyy  -Iyz ]
///   [-Ixz  -Iyz   Izz ]
/// with products of inertia defined as in seed eqs 3.97-3.100 (Ixz = sum dm x z), so that the
/// moment equations J w' + w x (J w) reproduce eqs 3.104-3.106 term by term.
struct MassProperties {
  double mass_kg = 1.0;
  Eigen::Matrix3d inertia_kgm2 = Eigen::Matrix3d::Identity();

  /// Builds the tensor from moments and products of inertia (book sign convention).
  static MassProperties from_moments(double mass_kg, double ixx_kgm2, double iyy_kgm2,
                                     double izz_kgm2, double ixz_kgm2 = 0.0, double ixy_kgm2 = 0.0,
                                     double iyz_kgm2 = 0.0);

  /// Throws std::invalid_argument unless the mass is positive and the tensor is symmetric,
  /// positive definite and satisfies the triangle inequalities of a physical body.
  void validate() const;
};

}  // namespace fedsim::flight
