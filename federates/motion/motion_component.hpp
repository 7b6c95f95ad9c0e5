// fedsim-motion's adapter (the seed's motion node, 1.4.9 and Chapter 10): every frame, the
// motion platform model (model/motion_platform.hpp: classical washout, soft workspace limit,
// Stewart inverse and forward kinematics, six jack actuators sub-stepped at >= 500 Hz, the
// safety state machine) steps on the aircraft's specific force at the pilot's eye point and its
// body rates, and fedsim/motion_state carries the delivered pose, the jacks and the cues.
//
// Engagement: with --engage (the default) the platform rises to neutral once the first valid
// aircraft state arrives, and cues while ENGAGED. Cut-off (the platform lowers to its parked
// position within the frame and latches MOTION_FAULT), each one reported by name as a fault:
//   - a non-finite or implausible aircraft-state sample ("input_rejected");
//   - the aircraft state silent for --silent-frames frames while cueing ("input_silent");
//   - a jack on its end stop, a following error, forward kinematics that fail ("motion_fault");
//   - the instructor: `fedsim command fail motion` ("motion_fault", reason "instructor cut-off").
// `fedsim command restore motion` clears the latched fault once the platform is down and
// engages it again. (The host steps the component on frame ticks; when ticks stop altogether no
// frame runs: the jacks' own servo loop, outside fedsim, holds the last command - left for the
// control-loading and motion issue's watchdog.)
#pragma once

#include "common/frame_clock/tick_gap_watch.hpp"
#include "common/runtime/component.hpp"
#include "common/runtime/federate_main.hpp"
#include "motion/model/motion_platform.hpp"

#include <memory>
#include <optional>
#include <string>

namespace fedsim::motion {

struct MotionSetup {
  MotionPlatformParameters parameters;
  bool engage_on_start = true;
  int silent_frames_limit = 10;  // frames without a new aircraft state that cut the motion off
  std::string state_qos;         // profile of fedsim/motion_state ("" = the catalogue's)
};

/// The motion cue inputs of an aircraft-state sample, or the reason it cannot be used.
std::optional<std::string> inputs_from_message(const msg::AircraftState& s, MotionInputs& out);
/// The motion-state message of the platform's outputs (no allocation but the reason string).
void to_message(const MotionPlatformOutputs& out, const std::string& fault_reason, msg::MotionPlatformState& msg);

class MotionComponent final : public runtime::Component {
 public:
  MotionComponent(std::string name, MotionSetup setup);

  void on_command(const msg::SimCommand& command) override;
  void step(const runtime::FrameContext& frame) override;
  /// Realtime (common/frame_clock/tick_gap_watch.hpp): a tick more than 1.5 frame periods late
  /// is ridden through (the last command held) and counted as a late tick; no tick for 2.5
  /// periods, or 3 late ticks within 50 frames, trips the platform ("motion_fault"), and the
  /// platform's own controller keeps stepping the park at the frame period on the wall clock,
  /// publishing each step, until the ticks come back.
  double tick_watchdog_periods() const override { return kTickWatchdogPeriods; }
  void on_ticks_stopped(const runtime::FrameContext& last, double silent_s) override;
  static constexpr double kTickWatchdogPeriods = timing::TickGapWatch::Limits{}.late_periods;
  /// Late ticks ridden through so far.
  std::uint64_t late_ticks() const { return tick_gaps_.late_ticks(); }

  /// The platform (nullptr before the first frame: it is built at the federation's period).
  const MotionPlatform* platform() const { return platform_.get(); }

 private:
  void take_aircraft_state(const runtime::FrameContext& frame);
  void apply_instructor();
  void report_status_change(const runtime::FrameContext& frame);

  // ---- Ports -------------------------------------------------------------------------------
  // reads  fedsim/aircraft_state: lockstep input, frame N cues the state of frame N-1
  //        (specific_force_eye_body_mps2, omega_body_radps: body axes, SI).
  runtime::Input<msg::AircraftState>& aircraft_state_;
  // writes fedsim/motion_state every frame (catalogue default "state", or --state-qos).
  runtime::Output<msg::MotionPlatformState>& motion_state_;

  MotionSetup setup_;
  std::unique_ptr<MotionPlatform> platform_;
  double platform_dt_s_ = 0.0;
  MotionInputs inputs_;                 // the latest valid cue inputs
  bool have_inputs_ = false;
  std::uint64_t updates_seen_ = 0;
  int silent_frames_ = 0;
  std::uint64_t park_steps_without_ticks_ = 0;  // wall-clock park steps since the last tick
  timing::TickGapWatch tick_gaps_;              // late ticks ridden through, stops, bursts
  bool instructor_cut_ = false;         // failed by the instructor, until restored
  bool restore_requested_ = false;      // restored: clear the fault once down, then engage
  bool engage_wanted_ = false;          // engage when parked (start, or after a restore)
  MotionStatus last_status_ = MotionStatus::kParked;
  msg::MotionPlatformState sample_;
};

/// fedsim-motion as a program: --parameters FILE (YAML, data/motion/README.md), --engage
/// on|off, --state-qos; the common --silent-frames N is also the silence that cuts the motion off.
runtime::FederateProgram program();

}  // namespace fedsim::motion
