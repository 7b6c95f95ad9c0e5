#include "motion/model/motion_parameter_file.hpp"

#include "common/units/units.hpp"

#include <stdexcept>

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

}  // namespace

MotionPlatformParameters read_motion_parameters(const util::ConfigNode& root, double frame_dt_s) {
  root.reject_unknown_keys({"washout", "platform"});
  MotionPlatformParameters p;
  if (root.has("washout")) read_washout(root.child("washout"), p.washout);
  if (root.has("platform")) read_platform(root.child("platform"), p);
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
