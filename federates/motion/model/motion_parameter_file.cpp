#include "motion/model/motion_parameter_file.hpp"

#include "common/units/units.hpp"
#include "motion/model/stewart_kinematics.hpp"

#include <algorithm>
#include <sstream>
#include <stdexcept>
#include <utility>

namespace fedsim::motion {
namespace {

constexpr const char* kAxisNames[3] = {"surge", "sway", "heave"};
constexpr const char* kRotationNames[3] = {"roll", "pitch", "yaw"};

void read_translational(const util::ConfigNode& node, TranslationalChannelParameters& p) {
  node.reject_unknown_keys({"gain", "natural_frequency_radps", "damping_ratio", "break_frequency_radps"});
  p.gain = node.number_or("gain", p.gain, 0.0, 1.0);
  p.natural_frequency_radps = node.number_or("natural_frequency_radps", p.natural_frequency_radps, 1e-3, 100.0);
  p.damping_ratio = node.number_or("damping_ratio", p.damping_ratio, 1e-3, 5.0);
  p.break_frequency_radps = node.number_or("break_frequency_radps", p.break_frequency_radps, 1e-4, 100.0);
}

void read_rotational(const util::ConfigNode& node, RotationalChannelParameters& p) {
  node.reject_unknown_keys({"gain", "natural_frequency_radps", "damping_ratio"});
  p.gain = node.number_or("gain", p.gain, 0.0, 1.0);
  p.natural_frequency_radps = node.number_or("natural_frequency_radps", p.natural_frequency_radps, 1e-3, 100.0);
  p.damping_ratio = node.number_or("damping_ratio", p.damping_ratio, 1e-3, 5.0);
}

void read_tilt(const util::ConfigNode& node, TiltCoordinationParameters& p) {
  node.reject_unknown_keys({"enabled", "gain", "natural_frequency_radps", "damping_ratio", "rate_limit_deg_s",
                            "angle_limit_deg"});
  p.enabled = node.boolean_or("enabled", p.enabled);
  p.gain = node.number_or("gain", p.gain, 0.0, 1.0);
  p.natural_frequency_radps = node.number_or("natural_frequency_radps", p.natural_frequency_radps, 1e-3, 100.0);
  p.damping_ratio = node.number_or("damping_ratio", p.damping_ratio, 1e-3, 5.0);
  // Degrees at the edge (a person tunes them), radians inside.
  p.rate_limit_radps =
      node.number_or("rate_limit_deg_s", p.rate_limit_radps * units::kRadToDeg, 1e-3, 20.0) * units::kDegToRad;
  p.angle_limit_rad =
      node.number_or("angle_limit_deg", p.angle_limit_rad * units::kRadToDeg, 1e-3, 45.0) * units::kDegToRad;
}

void read_washout(const util::ConfigNode& node, ClassicalWashoutParameters& w) {
  node.reject_unknown_keys({"translational", "rotational", "tilt", "specific_force_limit_mps2", "gravity_mps2"});
  w.specific_force_limit_mps2 = node.number_or("specific_force_limit_mps2", w.specific_force_limit_mps2, 1e-3, 100.0);
  w.gravity_mps2 = node.number_or("gravity_mps2", w.gravity_mps2, 9.0, 10.5);
  if (node.has("translational")) {
    const util::ConfigNode t = node.child("translational");
    t.reject_unknown_keys({"surge", "sway", "heave"});
    for (int i = 0; i < 3; ++i) {
      if (t.has(kAxisNames[i])) read_translational(t.child(kAxisNames[i]), w.translational[i]);
    }
  }
  if (node.has("rotational")) {
    const util::ConfigNode r = node.child("rotational");
    r.reject_unknown_keys({"roll", "pitch", "yaw"});
    for (int i = 0; i < 3; ++i) {
      if (r.has(kRotationNames[i])) read_rotational(r.child(kRotationNames[i]), w.rotational[i]);
    }
  }
  if (node.has("tilt")) read_tilt(node.child("tilt"), w.tilt);
}

void read_platform(const util::ConfigNode& node, MotionPlatformParameters& p) {
  node.reject_unknown_keys({"soft_limit_margin_m", "engage_speed_mps", "park_speed_mps", "actuator_rate_hz",
                            "command_speed_fraction", "following_error_limit_m"});
  p.soft_limit_margin_m = node.number_or("soft_limit_margin_m", p.soft_limit_margin_m, 0.0, 1.0);
  p.engage_speed_mps = node.number_or("engage_speed_mps", p.engage_speed_mps, 1e-3, 2.0);
  p.park_speed_mps = node.number_or("park_speed_mps", p.park_speed_mps, 1e-3, 2.0);
  p.actuator_rate_hz = node.number_or("actuator_rate_hz", p.actuator_rate_hz, 500.0, 20000.0);
  p.command_speed_fraction = node.number_or("command_speed_fraction", p.command_speed_fraction, 0.05, 1.0);
  p.following_error_limit_m = node.number_or("following_error_limit_m", p.following_error_limit_m, 1e-3, 2.0);
}


// A figure in (0, max]: number_or's range is closed, and a radius, length or limit of 0 is not
// physical (it would divide by zero or collapse the platform).
double positive_or(const util::ConfigNode& node, const std::string& key, double fallback, double max) {
  const double value = node.number_or(key, fallback, 0.0, max);
  if (!(value > 0.0)) node.fail_at(key, "must be > 0");
  return value;
}

// A half separation, in degrees at the edge: at 0 the two joints of a pair merge, at 30 deg
// the pairs of neighbouring jacks meet (stewart_geometry.hpp). Omitted, the radians stay
// exactly as built in (no round trip through degrees).
double half_separation_rad_or(const util::ConfigNode& node, const std::string& key, double fallback_rad) {
  if (!node.has(key)) return fallback_rad;
  const double deg = node.number(key, 0.0, 30.0);
  if (!(deg > 0.0 && deg < 30.0)) {
    node.fail_at(key, "must be in (0, 30) deg: the joints of a pair or of neighbouring pairs would meet");
  }
  return deg * units::kDegToRad;
}

std::string metres(double value_m) {
  std::ostringstream text;
  text << value_m << " m";
  return text.str();
}

// The symmetric design (stewart_geometry.hpp) from the file, over the built-in one; the stroke
// as its two lengths (the jack's catalogue figures), the neutral height only when given.
SymmetricStewartDesign read_design(const util::ConfigNode& node) {
  node.reject_unknown_keys({"base_radius_m", "top_radius_m", "base_half_separation_deg", "top_half_separation_deg",
                            "min_length_m", "max_length_m", "neutral_height_m"});
  SymmetricStewartDesign d = typical_60_inch_design();
  const double built_in_max_m = d.min_length_m + d.stroke_m;
  d.base_radius_m = positive_or(node, "base_radius_m", d.base_radius_m, 10.0);
  d.top_radius_m = positive_or(node, "top_radius_m", d.top_radius_m, 10.0);
  d.base_half_separation_rad = half_separation_rad_or(node, "base_half_separation_deg", d.base_half_separation_rad);
  d.top_half_separation_rad = half_separation_rad_or(node, "top_half_separation_deg", d.top_half_separation_rad);
  d.min_length_m = positive_or(node, "min_length_m", d.min_length_m, 20.0);
  const double max_length_m = positive_or(node, "max_length_m", built_in_max_m, 20.0);
  if (!(max_length_m > d.min_length_m)) {
    node.fail_at("max_length_m", "must be above min_length_m (" + metres(d.min_length_m) + ")");
  }
  d.stroke_m = max_length_m - d.min_length_m;
  if (node.has("neutral_height_m")) d.neutral_height_m = positive_or(node, "neutral_height_m", 0.0, 20.0);
  return d;
}

// The joints of the design. Every figure passed its own check, so the one way left to fail is
// a mid-stroke neutral the jacks cannot span (the radii too far apart for the jacks' length).
StewartGeometry place_joints(const util::ConfigNode& node, const SymmetricStewartDesign& d) {
  try {
    return place_symmetric_joints(d);
  } catch (const std::invalid_argument& e) {
    node.fail(std::string("the neutral pose is unreachable (base_radius_m, top_radius_m, the half separations "
                          "and min/max_length_m give no height with the jacks at mid-stroke): ") + e.what());
  }
}

// The jacks (JackActuatorParameters): the servo and the velocity and acceleration limits.
void read_actuator(const util::ConfigNode& node, JackActuatorParameters& a) {
  node.reject_unknown_keys({"natural_frequency_radps", "damping_ratio", "velocity_limit_mps",
                            "acceleration_limit_mps2", "cushion_deceleration_mps2"});
  a.natural_frequency_radps = positive_or(node, "natural_frequency_radps", a.natural_frequency_radps, 1000.0);
  a.damping_ratio = positive_or(node, "damping_ratio", a.damping_ratio, 5.0);
  a.velocity_limit_mps = positive_or(node, "velocity_limit_mps", a.velocity_limit_mps, 5.0);
  a.acceleration_limit_mps2 = positive_or(node, "acceleration_limit_mps2", a.acceleration_limit_mps2, 100.0);
  a.cushion_deceleration_mps2 = positive_or(node, "cushion_deceleration_mps2", a.cushion_deceleration_mps2, 100.0);
}

// A problem between fields, reported at `section.key`: on the key's line when the file sets
// it, else on the section's, else on the file's first line (the built-in value is at fault).
[[noreturn]] void fail_on(const util::ConfigNode& root, const std::string& section, const std::string& key,
                          const std::string& problem) {
  if (root.has(section)) root.child(section).fail_at(key, problem);
  root.fail_at(section + "." + key, problem);
}

// The soft workspace limit must leave room between the stroke ends (WorkspaceLimiter).
void check_margin(const util::ConfigNode& root, const MotionPlatformParameters& p) {
  const double half_stroke_m = 0.5 * p.geometry.stroke_m();
  if (!(p.soft_limit_margin_m < half_stroke_m)) {
    fail_on(root, "platform", "soft_limit_margin_m",
            "must be below half the jack stroke (" + metres(half_stroke_m) + ")");
  }
}

// The neutral pose, through the inverse kinematics, must put every jack inside the soft limits
// (the platform rises to it on engage and the limiter keeps it there): otherwise it would hit
// the stops or refuse to engage. Only a named neutral height can miss; a mid-stroke one cannot.
void check_neutral_reachable(const util::ConfigNode& root, const MotionPlatformParameters& p) {
  const double lower_m = p.geometry.min_length_m + p.soft_limit_margin_m;
  const double upper_m = p.geometry.max_length_m - p.soft_limit_margin_m;
  const JackArray neutral_m = jack_lengths_m(p.geometry, PlatformPose{});
  if (within(neutral_m, lower_m, upper_m)) return;
  const auto [shortest, longest] = std::minmax_element(neutral_m.begin(), neutral_m.end());
  std::ostringstream problem;
  problem << "the neutral pose is unreachable: the inverse kinematics give jacks of " << *shortest << " to "
          << *longest << " m there, outside [" << lower_m << ", " << upper_m
          << "] m (the stroke less platform.soft_limit_margin_m)";
  fail_on(root, "geometry", "neutral_height_m", problem.str());
}

// The jack servo is integrated at the actuator rate: stable and accurate for wa h <= 0.2
// (jack_actuator.hpp); the engage and park ramps must be within the jack's velocity limit.
void check_actuator(const util::ConfigNode& root, const MotionPlatformParameters& p) {
  const double max_frequency_radps = 0.2 * p.actuator_rate_hz;
  if (!(p.actuator.natural_frequency_radps <= max_frequency_radps)) {
    std::ostringstream problem;
    problem << "must be at most 0.2 x platform.actuator_rate_hz (" << max_frequency_radps << " rad/s)";
    fail_on(root, "actuator", "natural_frequency_radps", problem.str());
  }
  for (const auto& [key, speed] : {std::pair{"engage_speed_mps", p.engage_speed_mps},
                                   std::pair{"park_speed_mps", p.park_speed_mps}}) {
    if (!(speed <= p.actuator.velocity_limit_mps)) {
      std::ostringstream problem;
      problem << "must not exceed actuator.velocity_limit_mps (" << p.actuator.velocity_limit_mps << " m/s)";
      fail_on(root, "platform", key, problem.str());
    }
  }
}

}  // namespace

MotionPlatformParameters read_motion_parameters(const util::ConfigNode& root, double frame_dt_s) {
  root.reject_unknown_keys({"washout", "platform", "geometry", "actuator"});
  MotionPlatformParameters p;
  if (root.has("washout")) read_washout(root.child("washout"), p.washout);
  if (root.has("platform")) read_platform(root.child("platform"), p);
  if (root.has("actuator")) read_actuator(root.child("actuator"), p.actuator);
  if (root.has("geometry")) {
    const util::ConfigNode node = root.child("geometry");
    p.geometry = place_joints(node, read_design(node));
  }
  // Between sections, with the lines of the keys at fault, before validate() (which names the
  // field but not the line) sees the rest.
  check_margin(root, p);
  check_neutral_reachable(root, p);
  check_actuator(root, p);
  try {
    validate(p, frame_dt_s);
  } catch (const std::invalid_argument& e) {
    throw util::ConfigError(root.file() + ": " + e.what() + " (at a frame period of " +
                            std::to_string(frame_dt_s) + " s)");
  }
  return p;
}

MotionPlatformParameters load_motion_parameters(const std::string& path, double frame_dt_s) {
  return read_motion_parameters(util::ConfigNode::load_file(path), frame_dt_s);
}

MotionPlatformParameters parse_motion_parameters(const std::string& text, const std::string& origin,
                                                 double frame_dt_s) {
  return read_motion_parameters(util::ConfigNode::parse(text, origin), frame_dt_s);
}

}  // namespace fedsim::motion
