#include "motion/model/platform_pose.hpp"

#include <cmath>

namespace fedsim::motion {

PoseVector to_vector(const PlatformPose& pose) {
  PoseVector q;
  q << pose.position_i_m, pose.attitude.phi_rad, pose.attitude.theta_rad, pose.attitude.psi_rad;
  return q;
}

PlatformPose from_vector(const PoseVector& q) {
  PlatformPose pose;
  pose.position_i_m = q.head<3>();
  pose.attitude = EulerAngles{q(3), q(4), q(5)};
  return pose;
}

PlatformPose scaled(const PlatformPose& pose, double scale) {
  return from_vector(scale * to_vector(pose));
}

bool is_finite(const PlatformPose& pose) { return to_vector(pose).allFinite(); }

}  // namespace fedsim::motion
