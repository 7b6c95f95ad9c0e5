// The soft workspace limit: a demanded pose whose jack lengths leave the soft stroke
// [min_length + margin, max_length - margin] is never commanded; the limiter commands instead
// the pose on the straight line from neutral to the demand (all six components scaled by the
// same factor s in [0, 1]) where that line first leaves the soft workspace: the pose puts the
// most extended or retracted jack exactly on its soft limit. The cue keeps its direction and
// loses magnitude only, and as the washout brings the demand back inside, s returns to 1. s is
// found by a scan of the line in steps of 1/16 (the first scale outside) and then bisection
// between it and the last scale inside (the lengths are continuous in s and the neutral pose,
// s = 0, is inside): 40 halvings place the pose within 1e-12 of the boundary.
// The margin is the room the jacks keep for their end-stop cushions and servo overshoot.
#pragma once

#include "motion/model/platform_pose.hpp"
#include "motion/model/stewart_kinematics.hpp"

namespace fedsim::motion {

struct LimitedPose {
  PlatformPose pose;     // the pose to command
  JackArray lengths_m;   // its jack lengths [m]
  double scale = 1.0;    // s: 1 when the demand lies inside the soft workspace [-]
  bool limited = false;  // true when s < 1
};

class WorkspaceLimiter {
 public:
  /// margin_m: >= 0, less than half the stroke (else std::invalid_argument).
  WorkspaceLimiter(const StewartKinematics& kinematics, double margin_m);

  LimitedPose limit(const PlatformPose& demand) const;

  double lower_length_m() const { return lower_m_; }
  double upper_length_m() const { return upper_m_; }

 private:
  const StewartKinematics* kinematics_;
  double lower_m_;
  double upper_m_;
};

}  // namespace fedsim::motion
