// Attitude helpers: Euler angles, quaternions and direction cosines (seed 3.5.5 and 3.6).
// Quaternions are Hamilton (e0 = w scalar first) and rotate body vectors into the parent frame:
// v_parent = q * v_body, i.e. dcm_from_quaternion(q) is the matrix of eq. 3.63.
#pragma once

#include <Eigen/Core>
#include <Eigen/Geometry>

namespace fedsim {

/// 3-2-1 (yaw psi, pitch theta, roll phi) Euler angles of the body relative to a parent frame.
struct EulerAngles {
  double phi_rad = 0.0;
  double theta_rad = 0.0;
  double psi_rad = 0.0;
};

/// Quaternion from Euler angles (eqs 3.54-3.57).
Eigen::Quaterniond quaternion_from_euler(const EulerAngles& euler);

/// Direction cosine matrix parent_from_body (eq. 3.63); q need not be exactly unit length.
Eigen::Matrix3d dcm_from_quaternion(const Eigen::Quaterniond& q);
Eigen::Matrix3d dcm_from_euler(const EulerAngles& euler);

/// Euler angles from a parent_from_body DCM (eqs 3.64-3.66). Pitch uses atan2 so it stays
/// accurate near +-90 deg; at exactly +-90 deg (gimbal lock) roll is set to zero and the
/// heading carries the whole rotation about the vertical. psi in (-pi, pi].
EulerAngles euler_from_dcm(const Eigen::Matrix3d& parent_from_body);
EulerAngles euler_from_quaternion(const Eigen::Quaterniond& q);

/// Quaternion rate for body angular velocity omega (body axes, relative to the parent frame)
/// with the algebraic-constraint correction k * (1 - |q|^2) * q (eqs 3.59-3.62 and 3.67-3.70).
/// q is (e0, e1, e2, e3); choose k h <= 1 for step h.
Eigen::Vector4d quaternion_rate(const Eigen::Vector4d& q, const Eigen::Vector3d& omega_radps,
                                double constraint_gain_per_s);

/// Conversions between Eigen quaternions and the (e0, e1, e2, e3) vector used in state vectors.
Eigen::Vector4d to_e0123(const Eigen::Quaterniond& q);
Eigen::Quaterniond from_e0123(const Eigen::Vector4d& e);

/// Cross-product matrix: skew(a) * b == a.cross(b).
Eigen::Matrix3d skew(const Eigen::Vector3d& a);

/// Angle wrapped into (-pi, pi].
double wrap_pi(double angle_rad);

}  // namespace fedsim
