// The motion platform's parameters from a YAML file (data/motion/README.md documents the keys;
// data/motion/washout.yaml is the default tuning and platform, the same numbers as the structs'
// defaults and typical_60_inch_design()): washout, platform, geometry (the symmetric design of
// stewart_geometry.hpp) and actuator (the jacks). Every key is optional (the default stays; no
// geometry section = the built-in design), unknown keys are refused, numbers are range-checked
// on read, then the fields that depend on each other (the neutral pose, through the inverse
// kinematics, inside the jacks' soft limits; the servo against the actuator rate; the engage
// and park speeds against the velocity limit) and the whole set for the frame period: a bad
// file is a util::ConfigError naming file, line and field, before anything moves.
#pragma once

#include "common/util/config_node.hpp"
#include "motion/model/motion_platform.hpp"

#include <string>

namespace fedsim::motion {

/// Reads the file and validates the result for `frame_dt_s` (throws util::ConfigError).
MotionPlatformParameters load_motion_parameters(const std::string& path, double frame_dt_s);
/// The same from YAML text; `origin` names it in errors.
MotionPlatformParameters parse_motion_parameters(const std::string& text, const std::string& origin,
                                                 double frame_dt_s);
/// The same from a parsed node (the root of the file).
MotionPlatformParameters read_motion_parameters(const util::ConfigNode& root, double frame_dt_s);

}  // namespace fedsim::motion
