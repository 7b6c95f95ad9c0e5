#include "motion/model/stewart_kinematics.hpp"

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "common/math/rotation.hpp"

namespace fedsim::motion {
namespace {

// Elementary rotations of the 3-2-1 sequence (R = Rz(psi) Ry(theta) Rx(phi)) and their
// derivatives with respect to their angle.
Eigen::Matrix3d rx(double a) {
  Eigen::Matrix3d r;
  r << 1, 0, 0, 0, std::cos(a), -std::sin(a), 0, std::sin(a), std::cos(a);
  return r;
}
Eigen::Matrix3d ry(double a) {
  Eigen::Matrix3d r;
  r << std::cos(a), 0, std::sin(a), 0, 1, 0, -std::sin(a), 0, std::cos(a);
  return r;
}
Eigen::Matrix3d rz(double a) {
  Eigen::Matrix3d r;
  r << std::cos(a), -std::sin(a), 0, std::sin(a), std::cos(a), 0, 0, 0, 1;
  return r;
}
Eigen::Matrix3d drx(double a) {
  Eigen::Matrix3d r;
  r << 0, 0, 0, 0, -std::sin(a), -std::cos(a), 0, std::cos(a), -std::sin(a);
  return r;
}
Eigen::Matrix3d dry(double a) {
  Eigen::Matrix3d r;
  r << -std::sin(a), 0, std::cos(a), 0, 0, 0, -std::cos(a), 0, -std::sin(a);
  return r;
}
Eigen::Matrix3d drz(double a) {
  Eigen::Matrix3d r;
  r << -std::sin(a), -std::cos(a), 0, std::cos(a), -std::sin(a), 0, 0, 0, 0;
  return r;
}

void require_finite_pose(const PlatformPose& pose) {
  if (!is_finite(pose)) {
    throw std::invalid_argument("StewartKinematics: the pose is not finite");
  }
}

}  // namespace

StewartKinematics::StewartKinematics(const StewartGeometry& geometry) : geometry_(geometry) {
  validate(geometry_);
  neutral_lengths_m_ = inverse(PlatformPose{});
}

JackArray StewartKinematics::inverse(const PlatformPose& pose) const {
  require_finite_pose(pose);
  return jack_lengths_m(geometry_, pose);
}

JackArray jack_lengths_m(const StewartGeometry& geometry, const PlatformPose& pose) {
  const Eigen::Matrix3d i_from_p = dcm_from_euler(pose.attitude);
  JackArray lengths_m{};
  for (int k = 0; k < kJackCount; ++k) {
    const Eigen::Vector3d jack_i_m =
        pose.position_i_m + i_from_p * geometry.top_joints_p_m[k] - geometry.base_joints_i_m[k];
    lengths_m[k] = jack_i_m.norm();
  }
  return lengths_m;
}

PoseJacobian StewartKinematics::jacobian(const PlatformPose& pose) const {
  require_finite_pose(pose);
  const double phi = pose.attitude.phi_rad;
  const double theta = pose.attitude.theta_rad;
  const double psi = pose.attitude.psi_rad;
  const Eigen::Matrix3d r = rz(psi) * ry(theta) * rx(phi);
  const Eigen::Matrix3d dr_dphi = rz(psi) * ry(theta) * drx(phi);
  const Eigen::Matrix3d dr_dtheta = rz(psi) * dry(theta) * rx(phi);
  const Eigen::Matrix3d dr_dpsi = drz(psi) * ry(theta) * rx(phi);
  PoseJacobian j;
  for (int k = 0; k < kJackCount; ++k) {
    const Eigen::Vector3d& t = geometry_.top_joints_p_m[k];
    const Eigen::Vector3d jack_i_m = pose.position_i_m + r * t - geometry_.base_joints_i_m[k];
    const Eigen::Vector3d n = jack_i_m / jack_i_m.norm();
    j.block<1, 3>(k, 0) = n.transpose();
    j(k, 3) = n.dot(dr_dphi * t);
    j(k, 4) = n.dot(dr_dtheta * t);
    j(k, 5) = n.dot(dr_dpsi * t);
  }
  return j;
}

ForwardSolution StewartKinematics::forward(const JackArray& lengths_m,
                                           const PlatformPose& initial_guess, double tolerance_m,
                                           int max_iterations) const {
  for (double length_m : lengths_m) {
    if (!std::isfinite(length_m) || length_m <= 0.0) {
      throw std::invalid_argument("StewartKinematics::forward: a jack length is not positive");
    }
  }
  if (!(tolerance_m >= 1e-14) || max_iterations < 1) {
    throw std::invalid_argument(
        "StewartKinematics::forward: tolerance_m >= 1e-14, "
        "max_iterations >= 1");
  }
  ForwardSolution solution;
  PoseVector q = to_vector(initial_guess);
  Eigen::Matrix<double, kJackCount, 1> measured;
  for (int k = 0; k < kJackCount; ++k) measured(k) = lengths_m[k];
  for (int iteration = 0; iteration <= max_iterations; ++iteration) {
    const JackArray current = inverse(from_vector(q));
    Eigen::Matrix<double, kJackCount, 1> residual;
    for (int k = 0; k < kJackCount; ++k) residual(k) = current[k] - measured(k);
    solution.residual_m = residual.cwiseAbs().maxCoeff();
    solution.iterations = iteration;
    if (solution.residual_m <= tolerance_m) {
      solution.converged = true;
      break;
    }
    if (iteration == max_iterations || !std::isfinite(solution.residual_m)) break;
    q -= jacobian(from_vector(q)).fullPivLu().solve(residual);
  }
  solution.pose = from_vector(q);
  return solution;
}

bool within(const JackArray& lengths_m, double lower_m, double upper_m) {
  return std::all_of(lengths_m.begin(), lengths_m.end(),
                     [&](double l) { return l >= lower_m && l <= upper_m; });
}

}  // namespace fedsim::motion
