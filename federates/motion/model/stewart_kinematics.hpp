// Inverse and forward kinematics of a 6-6 Stewart platform.
//
// Inverse (closed form): jack k's vector from its base joint to its upper joint, in I, is
//   l_k = p + R t_k - b_k,   length L_k = |l_k|,
// with p the pose's position_i_m, R = i_from_p = dcm_from_euler(attitude) (3-2-1), t_k the
// upper joint in P and b_k the base joint in I.
//
// Forward (lengths -> pose, for monitoring the delivered motion): no closed form; Newton's
// method on the six equations L_k(q) - L_k,measured = 0 in q = (x, y, z, phi, theta, psi), with
// the analytic Jacobian dL_k/dq = n_k^T [I | dR/dphi t_k, dR/dtheta t_k, dR/dpsi t_k],
// n_k = l_k/L_k (Merlet, Parallel Robots, 2nd ed., 2006, ch. 4: the inverse Jacobian rows).
// Started from the previous pose (a frame apart) it converges quadratically in 2-3 iterations.
#pragma once

#include <Eigen/Core>

#include "motion/model/platform_pose.hpp"
#include "motion/model/stewart_geometry.hpp"

namespace fedsim::motion {

using PoseJacobian = Eigen::Matrix<double, kJackCount, 6>;  // dL_k/dq_j [m/m, m/rad]

struct ForwardSolution {
  PlatformPose pose;
  bool converged = false;
  int iterations = 0;
  double residual_m = 0.0;  // max |L_k(pose) - L_k| at the end [m]
};

class StewartKinematics {
 public:
  /// The geometry is validated (std::invalid_argument).
  explicit StewartKinematics(const StewartGeometry& geometry);

  /// Jack lengths [m] for a pose (finite; else std::invalid_argument).
  JackArray inverse(const PlatformPose& pose) const;
  /// dL/dq at a pose (rows: jacks; columns: x, y, z, phi, theta, psi).
  PoseJacobian jacobian(const PlatformPose& pose) const;

  /// The pose whose jack lengths are `lengths_m` [m], by Newton iteration from initial_guess,
  /// stopped when every length matches to tolerance_m [m] (>= 1e-14) or after max_iterations.
  ForwardSolution forward(const JackArray& lengths_m, const PlatformPose& initial_guess = {},
                          double tolerance_m = 1e-12, int max_iterations = 30) const;

  /// Lengths at neutral (the zero pose) [m].
  const JackArray& neutral_lengths_m() const { return neutral_lengths_m_; }
  const StewartGeometry& geometry() const { return geometry_; }

 private:
  StewartGeometry geometry_;
  JackArray neutral_lengths_m_;
};

/// The closed-form inverse kinematics on any geometry, its stroke not consulted: what
/// StewartKinematics::inverse computes, for checking a geometry before it is accepted.
JackArray jack_lengths_m(const StewartGeometry& geometry, const PlatformPose& pose);

/// True when every length lies in [lower_m, upper_m].
bool within(const JackArray& lengths_m, double lower_m, double upper_m);

}  // namespace fedsim::motion
