#include "motion/model/motion_platform.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>
#include <stdexcept>

#include "common/control/parameter_checks.hpp"
#include "common/math/rotation.hpp"

namespace fedsim::motion {
namespace {

constexpr const char* kBlock = "MotionPlatformParameters";
constexpr double kMinActuatorRateHz = 500.0;

JackArray filled(double value) {
  JackArray a{};
  a.fill(value);
  return a;
}

}  // namespace

const char* to_string(MotionStatus status) {
  switch (status) {
    case MotionStatus::kParked:
      return "parked";
    case MotionStatus::kEngaging:
      return "engaging";
    case MotionStatus::kEngaged:
      return "engaged";
    case MotionStatus::kParking:
      return "parking";
    case MotionStatus::kFault:
      return "fault";
  }
  return "unknown";
}

void validate(const MotionPlatformParameters& p, double frame_dt_s) {
  validate(p.washout, frame_dt_s);
  validate(p.geometry);
  validate(p.actuator);
  control::require_non_negative(kBlock, "soft_limit_margin_m", p.soft_limit_margin_m);
  control::require_positive(kBlock, "engage_speed_mps", p.engage_speed_mps);
  control::require_positive(kBlock, "park_speed_mps", p.park_speed_mps);
  control::require_positive(kBlock, "actuator_rate_hz", p.actuator_rate_hz);
  if (p.actuator_rate_hz < kMinActuatorRateHz) {
    throw std::invalid_argument("MotionPlatformParameters: actuator_rate_hz must be >= 500");
  }
  if (p.engage_speed_mps > p.actuator.velocity_limit_mps ||
      p.park_speed_mps > p.actuator.velocity_limit_mps) {
    throw std::invalid_argument(
        "MotionPlatformParameters: engage and park speeds must not exceed the jack velocity "
        "limit");
  }
  control::require_positive_at_most(kBlock, "command_speed_fraction", p.command_speed_fraction,
                                    1.0);
  control::require_positive(kBlock, "following_error_limit_m", p.following_error_limit_m);
  control::require_positive(kBlock, "settled_tolerance_m", p.settled_tolerance_m);
  control::require_positive(kBlock, "settled_speed_mps", p.settled_speed_mps);
  control::require_positive(kBlock, "specific_force_input_limit_mps2",
                            p.specific_force_input_limit_mps2);
  control::require_positive(kBlock, "angular_rate_input_limit_radps",
                            p.angular_rate_input_limit_radps);
}

MotionPlatform::MotionPlatform(const MotionPlatformParameters& parameters, double frame_dt_s)
    : parameters_((validate(parameters, frame_dt_s), parameters)),
      frame_dt_s_(frame_dt_s),
      substeps_(static_cast<int>(std::ceil(frame_dt_s * parameters.actuator_rate_hz - 1e-9))),
      kinematics_(std::make_unique<StewartKinematics>(parameters.geometry)),
      limiter_(*kinematics_, parameters.soft_limit_margin_m),
      washout_(parameters.washout, frame_dt_s) {
  substeps_ = std::max(substeps_, 1);
  const double substep_s = frame_dt_s / substeps_;
  const StewartGeometry& g = parameters_.geometry;
  for (int k = 0; k < kJackCount; ++k) {
    jacks_.emplace_back(parameters_.actuator, g.min_length_m, g.max_length_m, substep_s,
                        g.min_length_m);
  }
  retracted_m_ = filled(g.min_length_m);
  previous_command_m_ = command_m_ = retracted_m_;
  outputs_.jack_length_m = outputs_.jack_command_m = retracted_m_;
  const ForwardSolution parked = kinematics_->forward(retracted_m_);
  if (!parked.converged) {
    throw std::invalid_argument("MotionPlatform: no pose for the retracted jack lengths");
  }
  outputs_.pose = outputs_.commanded_pose = parked.pose;
}

bool MotionPlatform::engage() {
  if (outputs_.status != MotionStatus::kParked) return false;
  outputs_.status = MotionStatus::kEngaging;
  start_ramp_from_present_lengths();
  return true;
}

bool MotionPlatform::park() {
  if (outputs_.status != MotionStatus::kEngaging && outputs_.status != MotionStatus::kEngaged) {
    return false;
  }
  outputs_.status = MotionStatus::kParking;
  start_ramp_from_present_lengths();
  return true;
}

void MotionPlatform::trip(const std::string& reason) {
  if (fault_reason_.empty()) fault_reason_ = reason.empty() ? "unspecified" : reason;
  if (outputs_.status == MotionStatus::kFault) return;
  outputs_.status = MotionStatus::kFault;
  start_ramp_from_present_lengths();
}

bool MotionPlatform::clear_fault() {
  if (outputs_.status != MotionStatus::kFault || !settled_at(retracted_m_)) return false;
  outputs_.status = MotionStatus::kParked;
  fault_reason_.clear();
  return true;
}

// The ramp continues from where the jacks are, so the command is continuous with the motion.
void MotionPlatform::start_ramp_from_present_lengths() {
  for (int k = 0; k < kJackCount; ++k) command_m_[k] = jacks_[k].length_m();
}

bool MotionPlatform::inputs_valid(const MotionInputs& in, std::string& problem) const {
  const Eigen::Vector3d& f = in.specific_force_eye_body_mps2;
  const Eigen::Vector3d& w = in.omega_body_radps;
  if (!f.allFinite() || f.cwiseAbs().maxCoeff() > parameters_.specific_force_input_limit_mps2) {
    problem = "input rejected: specific_force_eye_body_mps2 not finite or beyond its limit";
    return false;
  }
  if (!w.allFinite() || w.cwiseAbs().maxCoeff() > parameters_.angular_rate_input_limit_radps) {
    problem = "input rejected: omega_body_radps not finite or beyond its limit";
    return false;
  }
  return true;
}

void MotionPlatform::ramp_commands_towards(const JackArray& target_m, double speed_mps) {
  const double max_step_m = speed_mps * frame_dt_s_;
  for (int k = 0; k < kJackCount; ++k) {
    command_m_[k] += std::clamp(target_m[k] - command_m_[k], -max_step_m, max_step_m);
  }
}

bool MotionPlatform::settled_at(const JackArray& target_m) const {
  for (int k = 0; k < kJackCount; ++k) {
    if (std::abs(jacks_[k].length_m() - target_m[k]) > parameters_.settled_tolerance_m ||
        std::abs(jacks_[k].velocity_mps()) > parameters_.settled_speed_mps) {
      return false;
    }
  }
  return true;
}

void MotionPlatform::command_engaged(const MotionInputs& inputs) {
  const WashoutOutput& cue =
      washout_.step(WashoutInput{inputs.specific_force_eye_body_mps2, inputs.omega_body_radps});
  const LimitedPose limited = slowed_to_jack_speed(limiter_.limit(cue.pose));
  outputs_.demanded_pose = cue.pose;
  outputs_.commanded_pose = limited.pose;
  outputs_.workspace_scale = limited.scale;
  outputs_.workspace_limited = limited.limited;
  outputs_.specific_force_washout_p_mps2 = cue.specific_force_cue_p_mps2;
  command_m_ = limited.lengths_m;
}

// The step from last frame's commanded pose towards the target, shortened (same direction in
// pose space) so that no jack command moves more than the allowed speed times the frame.
LimitedPose MotionPlatform::slowed_to_jack_speed(const LimitedPose& target) {
  const double max_step_m =
      parameters_.command_speed_fraction * parameters_.actuator.velocity_limit_mps * frame_dt_s_;
  double largest_step_m = 0.0;
  for (int k = 0; k < kJackCount; ++k) {
    largest_step_m = std::max(largest_step_m, std::abs(target.lengths_m[k] - command_m_[k]));
  }
  outputs_.command_rate_limited = largest_step_m > max_step_m;
  if (!outputs_.command_rate_limited) return target;
  const PoseVector from = to_vector(outputs_.commanded_pose);
  const double fraction = max_step_m / largest_step_m;
  LimitedPose slowed =
      limiter_.limit(from_vector(from + fraction * (to_vector(target.pose) - from)));
  slowed.limited = slowed.limited || target.limited;
  slowed.scale = std::min(slowed.scale, target.scale);
  return slowed;
}

// The command moves linearly from last frame's to this frame's over the sub-steps.
void MotionPlatform::run_actuators() {
  outputs_.jack_rate_limited = outputs_.jack_cushioned = false;
  for (int n = 1; n <= substeps_; ++n) {
    const double fraction = static_cast<double>(n) / substeps_;
    for (int k = 0; k < kJackCount; ++k) {
      jacks_[k].step(previous_command_m_[k] + fraction * (command_m_[k] - previous_command_m_[k]));
      outputs_.jack_rate_limited = outputs_.jack_rate_limited || jacks_[k].rate_limited();
      outputs_.jack_cushioned = outputs_.jack_cushioned || jacks_[k].cushioned();
    }
  }
  previous_command_m_ = command_m_;
  for (int k = 0; k < kJackCount; ++k) {
    outputs_.jack_length_m[k] = jacks_[k].length_m();
    outputs_.jack_velocity_mps[k] = jacks_[k].velocity_mps();
  }
  outputs_.jack_command_m = command_m_;
}

void MotionPlatform::monitor_engaged() {
  for (int k = 0; k < kJackCount; ++k) {
    if (jacks_[k].at_end_stop()) {
      trip("jack " + std::to_string(k) + " on its end stop while engaged");
      return;
    }
    if (std::abs(command_m_[k] - jacks_[k].length_m()) > parameters_.following_error_limit_m) {
      trip("jack " + std::to_string(k) + " following error beyond the limit");
      return;
    }
  }
}

// Forward kinematics of the jack lengths from last frame's pose; the delivered specific force
// from the second difference of the delivered position (a_i - g_i, in P).
void MotionPlatform::update_delivered_motion() {
  const ForwardSolution solution = kinematics_->forward(outputs_.jack_length_m, outputs_.pose);
  outputs_.forward_iterations = solution.iterations;
  if (!solution.converged) {
    trip("forward kinematics did not converge");
    return;
  }
  outputs_.pose = solution.pose;
  if (outputs_.status != MotionStatus::kEngaged) outputs_.commanded_pose = solution.pose;
  const Eigen::Vector3d& position = solution.pose.position_i_m;
  Eigen::Vector3d acceleration_i = Eigen::Vector3d::Zero();
  if (position_history_ >= 2) {
    acceleration_i = (position - 2.0 * previous_position_m_ + before_previous_position_m_) /
                     (frame_dt_s_ * frame_dt_s_);
  }
  position_history_ = std::min(position_history_ + 1, 2);
  before_previous_position_m_ = previous_position_m_;
  previous_position_m_ = position;
  const Eigen::Vector3d g_i(0.0, 0.0, parameters_.washout.gravity_mps2);
  outputs_.specific_force_cue_p_mps2 =
      dcm_from_euler(solution.pose.attitude).transpose() * (acceleration_i - g_i);
}

const MotionPlatformOutputs& MotionPlatform::step(const MotionInputs& inputs) {
  std::string problem;
  const bool valid = inputs_valid(inputs, problem);
  if (!valid) trip(problem);
  outputs_.specific_force_demand_mps2 =
      valid ? inputs.specific_force_eye_body_mps2 : Eigen::Vector3d::Zero();
  outputs_.workspace_limited = outputs_.command_rate_limited = false;
  outputs_.workspace_scale = 1.0;
  if (outputs_.status != MotionStatus::kEngaged) {
    outputs_.demanded_pose = PlatformPose{};
    outputs_.specific_force_washout_p_mps2 =
        -Eigen::Vector3d(0, 0, parameters_.washout.gravity_mps2);
  }

  switch (outputs_.status) {
    case MotionStatus::kParked:
      command_m_ = retracted_m_;
      break;
    case MotionStatus::kEngaging:
      ramp_commands_towards(kinematics_->neutral_lengths_m(), parameters_.engage_speed_mps);
      break;
    case MotionStatus::kEngaged:
      command_engaged(inputs);
      break;
    case MotionStatus::kParking:
    case MotionStatus::kFault:
      ramp_commands_towards(retracted_m_, parameters_.park_speed_mps);
      break;
  }
  run_actuators();
  if (outputs_.status == MotionStatus::kEngaged) monitor_engaged();
  update_delivered_motion();

  if (outputs_.status == MotionStatus::kEngaging && settled_at(kinematics_->neutral_lengths_m())) {
    outputs_.status = MotionStatus::kEngaged;
    outputs_.commanded_pose = PlatformPose{};  // the ramp ended on the neutral lengths
    washout_.reset(WashoutInput{inputs.specific_force_eye_body_mps2, inputs.omega_body_radps});
  } else if (outputs_.status == MotionStatus::kParking && settled_at(retracted_m_)) {
    outputs_.status = MotionStatus::kParked;
  }
  return outputs_;
}

}  // namespace fedsim::motion
