// The motion platform as the motion federate runs it, once per frame (frame_dt_s): the
// classical washout, the soft workspace limiter, the inverse kinematics, six jack actuators
// sub-stepped at actuator_rate_hz (>= 500 Hz, seed 1.4.9: "updated at rates in excess of
// 500 Hz"), the forward kinematics of the jack lengths (the pose actually delivered) and the
// safety state machine:
//
//   PARKED --engage()--> ENGAGING --(at neutral, settled)--> ENGAGED
//   ENGAGING/ENGAGED --park()--> PARKING --(at min length, settled)--> PARKED
//   any --trip(reason) or a detected fault--> FAULT: parks as PARKING does and stays FAULT
//   (latched) until clear_fault() once settled, which gives PARKED.
//
// While engaged, the commanded pose is the washout's demand, limited to the soft workspace
// (WorkspaceLimiter) and slowed so that no jack command moves faster than
// command_speed_fraction x the jack velocity limit: the pose moves towards the limited demand
// along the straight line in pose space, so a demand the jacks cannot follow is delivered late
// but undistorted, and the servos keep a small following error.
// Engaging and parking move every jack command at a bounded speed (engage_speed_mps,
// park_speed_mps) from the jack's present length towards neutral or the retracted length
// (seed 1.4.9: on an emergency "the hydraulic system should lower the platform to its lowest
// point"). A fault is detected (within the frame it happens in) on: a non-finite or implausible
// input, a jack on its mechanical end stop while engaged, a following error beyond
// following_error_limit_m, forward kinematics that do not converge. The washout starts from
// neutral without a transient on entering ENGAGED (ClassicalWashout::reset).
//
// Inputs (MotionInputs): the aircraft's specific force at the pilot's eye point and body rates
// (body axes, SI). Outputs (MotionPlatformOutputs): the status, the demanded, commanded and
// delivered poses (frames I/P, platform_pose.hpp), jack lengths, rates and commands, and the
// specific force demanded and delivered (from the delivered pose's acceleration).
#pragma once

#include <Eigen/Core>
#include <memory>
#include <string>
#include <vector>

#include "motion/model/classical_washout.hpp"
#include "motion/model/jack_actuator.hpp"
#include "motion/model/platform_pose.hpp"
#include "motion/model/stewart_geometry.hpp"
#include "motion/model/stewart_kinematics.hpp"
#include "motion/model/washout_parameters.hpp"
#include "motion/model/workspace_limiter.hpp"

namespace fedsim::motion {

enum class MotionStatus { kParked, kEngaging, kEngaged, kParking, kFault };
const char* to_string(MotionStatus status);

struct MotionPlatformParameters {
  ClassicalWashoutParameters washout;
  StewartGeometry geometry = make_symmetric_geometry(typical_60_inch_design());
  JackActuatorParameters actuator;
  double soft_limit_margin_m = 0.05;      // workspace limit this far inside each stroke end [m]
  double engage_speed_mps = 0.15;         // jack speed while rising to neutral [m/s]
  double park_speed_mps = 0.10;           // jack speed while settling to the retracted length [m/s]
  double actuator_rate_hz = 1000.0;       // jack sub-step rate, >= 500 [Hz]
  double command_speed_fraction = 0.9;    // jack commands move at most this x velocity limit [-]
  double following_error_limit_m = 0.25;  // |command - length| that trips a fault [m]
  double settled_tolerance_m = 1e-3;      // "at neutral" / "parked": every jack this close [m]
  double settled_speed_mps = 1e-3;        // ... and slower than this [m/s]
  double specific_force_input_limit_mps2 = 100.0;  // |f| per axis beyond this: invalid [m/s^2]
  double angular_rate_input_limit_radps = 10.0;    // |omega| per axis beyond this: invalid [rad/s]
};

/// Checks every field (std::invalid_argument naming it); the washout for frame_dt_s.
void validate(const MotionPlatformParameters& parameters, double frame_dt_s);

struct MotionInputs {
  Eigen::Vector3d specific_force_eye_body_mps2 = {0.0, 0.0, -9.80665};  // [m/s^2]
  Eigen::Vector3d omega_body_radps = Eigen::Vector3d::Zero();           // [rad/s]
};

struct MotionPlatformOutputs {
  MotionStatus status = MotionStatus::kParked;
  PlatformPose demanded_pose;   // washout output (neutral when not engaged)
  PlatformPose commanded_pose;  // after the workspace limiter (the delivered pose when not engaged)
  PlatformPose pose;            // delivered: forward kinematics of the jack lengths
  JackArray jack_length_m{};
  JackArray jack_velocity_mps{};
  JackArray jack_command_m{};    // the command at the end of the frame [m]
  double workspace_scale = 1.0;  // WorkspaceLimiter's s [-]
  bool workspace_limited = false;
  bool command_rate_limited = false;  // the commanded pose was slowed to the jacks' speed
  bool jack_rate_limited = false;     // some jack velocity/acceleration limited in this frame
  bool jack_cushioned = false;        // some jack braked in its end cushion in this frame
  Eigen::Vector3d specific_force_demand_mps2 = Eigen::Vector3d::Zero();     // the input, body
  Eigen::Vector3d specific_force_washout_p_mps2 = Eigen::Vector3d::Zero();  // ideal cue, P
  Eigen::Vector3d specific_force_cue_p_mps2 = Eigen::Vector3d::Zero();      // delivered, P
  int forward_iterations = 0;
};

class MotionPlatform {
 public:
  /// Parameters validated (std::invalid_argument). Starts PARKED, jacks at min length.
  MotionPlatform(const MotionPlatformParameters& parameters, double frame_dt_s);

  /// PARKED -> ENGAGING; false (nothing changes) in any other state.
  bool engage();
  /// ENGAGING or ENGAGED -> PARKING; false otherwise.
  bool park();
  /// -> FAULT with the reason (kept until cleared; a later trip keeps the first reason).
  void trip(const std::string& reason);
  /// FAULT and settled at the retracted length -> PARKED; false otherwise.
  bool clear_fault();

  /// One frame. An invalid input trips a fault (the frame then runs on the fault path).
  const MotionPlatformOutputs& step(const MotionInputs& inputs);

  MotionStatus status() const { return outputs_.status; }
  const std::string& fault_reason() const { return fault_reason_; }
  const MotionPlatformOutputs& outputs() const { return outputs_; }
  const StewartKinematics& kinematics() const { return *kinematics_; }
  int substeps_per_frame() const { return substeps_; }
  double frame_dt_s() const { return frame_dt_s_; }

 private:
  bool inputs_valid(const MotionInputs& inputs, std::string& problem) const;
  void ramp_commands_towards(const JackArray& target_m, double speed_mps);
  bool settled_at(const JackArray& target_m) const;
  void command_engaged(const MotionInputs& inputs);
  LimitedPose slowed_to_jack_speed(const LimitedPose& target);
  void run_actuators();
  void monitor_engaged();
  void update_delivered_motion();
  void start_ramp_from_present_lengths();

  MotionPlatformParameters parameters_;
  double frame_dt_s_;
  int substeps_;
  std::unique_ptr<StewartKinematics> kinematics_;  // stable address for the limiter
  WorkspaceLimiter limiter_;
  ClassicalWashout washout_;
  std::vector<JackActuator> jacks_;
  JackArray retracted_m_{};
  JackArray previous_command_m_{};
  JackArray command_m_{};
  MotionPlatformOutputs outputs_;
  std::string fault_reason_;
  Eigen::Vector3d previous_position_m_ = Eigen::Vector3d::Zero();
  Eigen::Vector3d before_previous_position_m_ = Eigen::Vector3d::Zero();
  int position_history_ = 0;  // frames of delivered position held (0..2)
};

}  // namespace fedsim::motion
