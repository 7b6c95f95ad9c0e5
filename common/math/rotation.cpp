// Attitude helpers: Euler angles, quaternions and direction cosines.
#include "common/math/rotation.hpp"
#include "common/units/units.hpp"

#include <cmath>

namespace fedsim {

namespace {
// Below this cos(theta) the roll and yaw axes coincide and only their sum/difference is defined.
constexpr double kGimbalLockCosine = 1e-12;
}  // namespace

Eigen::Quaterniond quaternion_from_euler(const EulerAngles& euler) {
  const double cp = std::cos(0.5 * euler.phi_rad);
  const double sp = std::sin(0.5 * euler.phi_rad);
  const double ct = std::cos(0.5 * euler.theta_rad);
  const double st = std::sin(0.5 * euler.theta_rad);
  const double cs = std::cos(0.5 * euler.psi_rad);
  const double ss = std::sin(0.5 * euler.psi_rad);
  return Eigen::Quaterniond(cs * ct * cp + ss * st * sp,   // e0, eq. 3.54
                            cs * ct * sp - ss * st * cp,   // e1, eq. 3.55
                            cs * st * cp + ss * ct * sp,   // e2, eq. 3.56
                            ss * ct * cp - cs * st * sp);  // e3, eq. 3.57
}

Eigen::Matrix3d dcm_from_quaternion(const Eigen::Quaterniond& q) {
  const double e0 = q.w();
  const double e1 = q.x();
  const double e2 = q.y();
  const double e3 = q.z();
  Eigen::Matrix3d a;
  a << e0 * e0 + e1 * e1 - e2 * e2 - e3 * e3, 2.0 * (e1 * e2 - e0 * e3), 2.0 * (e0 * e2 + e1 * e3),
      2.0 * (e1 * e2 + e0 * e3), e0 * e0 - e1 * e1 + e2 * e2 - e3 * e3, 2.0 * (e2 * e3 - e0 * e1),
      2.0 * (e1 * e3 - e0 * e2), 2.0 * (e2 * e3 + e0 * e1), e0 * e0 - e1 * e1 - e2 * e2 + e3 * e3;
  return a / q.squaredNorm();  // a unit-norm DCM even if the quaternion has drifted slightly
}

Eigen::Matrix3d dcm_from_euler(const EulerAngles& euler) {
  return dcm_from_quaternion(quaternion_from_euler(euler));
}

EulerAngles euler_from_dcm(const Eigen::Matrix3d& a) {
  EulerAngles euler;
  const double cos_theta = std::hypot(a(2, 1), a(2, 2));
  euler.theta_rad = std::atan2(-a(2, 0), cos_theta);  // eq. 3.64 in atan2 form
  if (cos_theta > kGimbalLockCosine) {
    euler.phi_rad = std::atan2(a(2, 1), a(2, 2));  // eq. 3.65
    euler.psi_rad = std::atan2(a(1, 0), a(0, 0));  // eq. 3.66
  } else {
    // theta = +-90 deg: with phi = 0, a12 = -sin(psi) and a22 = cos(psi) for either sign.
    euler.phi_rad = 0.0;
    euler.psi_rad = std::atan2(-a(0, 1), a(1, 1));
  }
  return euler;
}

EulerAngles euler_from_quaternion(const Eigen::Quaterniond& q) {
  return euler_from_dcm(dcm_from_quaternion(q));
}

Eigen::Vector4d quaternion_rate(const Eigen::Vector4d& q, const Eigen::Vector3d& omega_radps,
                                double constraint_gain_per_s) {
  const double p = omega_radps.x();
  const double r_q = omega_radps.y();
  const double r = omega_radps.z();
  const double lambda = 1.0 - q.squaredNorm();
  const double k_lambda = constraint_gain_per_s * lambda;
  return {-0.5 * (q[1] * p + q[2] * r_q + q[3] * r) + k_lambda * q[0],  // eq. 3.67
          0.5 * (q[0] * p + q[2] * r - q[3] * r_q) + k_lambda * q[1],   // eq. 3.68
          0.5 * (q[0] * r_q + q[3] * p - q[1] * r) + k_lambda * q[2],   // eq. 3.69
          0.5 * (q[0] * r + q[1] * r_q - q[2] * p) + k_lambda * q[3]};  // eq. 3.70
}

Eigen::Vector4d to_e0123(const Eigen::Quaterniond& q) { return {q.w(), q.x(), q.y(), q.z()}; }

Eigen::Quaterniond from_e0123(const Eigen::Vector4d& e) {
  return Eigen::Quaterniond(e[0], e[1], e[2], e[3]);
}

Eigen::Matrix3d skew(const Eigen::Vector3d& a) {
  Eigen::Matrix3d s;
  s << 0.0, -a.z(), a.y(), a.z(), 0.0, -a.x(), -a.y(), a.x(), 0.0;
  return s;
}

double wrap_pi(double angle_rad) {
  double wrapped = std::remainder(angle_rad, 2.0 * units::kPi);
  if (wrapped <= -units::kPi) wrapped += 2.0 * units::kPi;
  return wrapped;
}

}  // namespace fedsim
