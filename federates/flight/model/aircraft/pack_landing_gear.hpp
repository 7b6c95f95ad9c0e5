// Landing-gear section of an aircraft pack: ground contact points and their strut figures (SI).
#pragma once

#include <Eigen/Dense>
#include <string>
#include <vector>

namespace fedsim::flight {

enum class ContactType { wheel, structure };
enum class BrakeGroup { none, left, right };

/// One ground contact (seed 3.9): a spring-damper strut at a point, with friction.
struct GearContactSpec {
  std::string name;
  ContactType type = ContactType::wheel;
  Eigen::Vector3d position_m = Eigen::Vector3d::Zero();  // uncompressed contact point, pack frame
  double spring_n_per_m = 0.0;
  double damping_n_s_per_m = 0.0;          // while compressing
  double rebound_damping_n_s_per_m = 0.0;  // while extending
  double static_friction = 0.0;
  double dynamic_friction = 0.0;
  double rolling_friction = 0.0;
  double max_steer_rad = 0.0;              // 0: not steerable
  BrakeGroup brake_group = BrakeGroup::none;
  bool retractable = false;
};

struct LandingGearSpec {
  double transit_time_s = 0.0;  // time to extend or retract the retractable contacts
  std::vector<GearContactSpec> contacts;
};

}  // namespace fedsim::flight
