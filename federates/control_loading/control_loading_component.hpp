// fedsim-control-loading's adapter (seed 1.4.10): every frame, the three-axis control loader
// (model/control_loading.hpp: mass-spring-damper controls with breakout, friction, a gradient
// scheduled with dynamic pressure, trim datum, soft and hard stops, stick shaker and autopilot
// back-drive, sub-stepped at >= 1 kHz inside the frame, with its safety cut-off) steps on the
// aircraft state (dynamic pressure, angle of attack and their age), the pilot's controls and the
// autopilot's commands, and fedsim/control_loading_state carries each control's position,
// velocity, felt force and trim datum.
//
// The pilot: with force sensors (fedsim/pilot_controls carries DISCRETE_FORCE_SENSORS and
// pilot_force_n: the I/O federate's --loader-in-the-loop) the pilot's forces move the controls
// against the feel, and the I/O federate reports the positions as the primaries
// (io_component.hpp documents the loop). Without them the simulated pilot of the model holds
// each control where fedsim/pilot_controls puts it (elevator, aileron, rudder; trims move the
// datum): the loader then reports the force that takes against the feel. (With the flight federate's
// --controls relative, those primaries are offsets from the trimmed surfaces: the loader shows
// them about its centre, the trim datum following the trim controls.) The autopilot back-drives the
// column and wheel while CMD is engaged, the pedals in rollout (fedsim/autopilot_state, monitored:
// a federation without the autopilot is not held back; a state 3 frames old no longer drives);
// meanwhile the pilot is hands and feet off.
//
// Engages once the first valid aircraft state arrives (--engage). Cut off to SAFE within the
// frame, reported by name: a non-finite sample ("input_rejected"), flight data older than the
// watchdog, an overspeed, frame ticks that stop arriving in realtime (no tick for 2.5 frame
// periods or 3 late ticks within 50 frames; one late tick is ridden through and counted:
// "control_loading_cut_off"), the instructor (`fedsim command fail
// control_loading`; `restore control_loading` engages it again).
#pragma once

#include "common/frame_clock/tick_gap_watch.hpp"
#include "common/runtime/component.hpp"
#include "common/runtime/federate_main.hpp"
#include "control_loading/model/control_loading.hpp"

#include <optional>
#include <string>
#include <vector>

namespace fedsim::control_loading {

struct ControlLoadingSetup {
  ControlLoadingParameters parameters;
  // The stick shaker's angle against the flap position (--aircraft: the pack's stall-warning
  // schedule, common/aircraft_pack), interpolated linearly; empty: the parameters' fixed
  // shaker_alpha_rad.
  std::vector<double> shaker_flap_norm;
  std::vector<double> shaker_alpha_rad;
  bool engage_on_start = true;
  std::string state_qos;  // profile of fedsim/control_loading_state ("" = the catalogue's)
};

/// The shaker angle of the schedule at flap position `flap_norm` (clamped to its ends); NaN for
/// an empty schedule.
double scheduled_shaker_alpha_rad(const ControlLoadingSetup& setup, double flap_norm);
/// The schedule of a pack (--aircraft): its stated stall-warning angles (1.05 V_s: the flight
/// model checks them against the pack's lift) at its flap settings. Throws
/// std::invalid_argument naming the pack when it states none.
void schedule_shaker_from_pack(const std::string& pack_path, ControlLoadingSetup& setup);

/// The loader's inputs from the latest samples; the reason one cannot be used, or nullopt.
/// `autopilot` may be null (no autopilot in the federation).
std::optional<std::string> inputs_from_messages(const msg::AircraftState& aircraft, double now_s,
                                                const msg::PilotControls* pilot,
                                                const msg::AutopilotState* autopilot, ControlLoadingInputs& out);
/// The control-loading message of the loader's outputs.
void to_message(const ControlLoadingOutputs& out, const ControlLoadingInputs& in, const std::string& reason,
                msg::ControlLoadingState& msg);

class ControlLoadingComponent final : public runtime::Component {
 public:
  ControlLoadingComponent(std::string name, ControlLoadingSetup setup);

  void on_command(const msg::SimCommand& command) override;
  void step(const runtime::FrameContext& frame) override;
  /// Realtime (common/frame_clock/tick_gap_watch.hpp): a tick more than 1.5 frame periods late
  /// is ridden through (the forces held) and counted as a late tick; no tick for 2.5 periods,
  /// or 3 late ticks within 50 frames, cuts the loader off, reported as control_loading_cut_off,
  /// and publishes the SAFE state; it stays SAFE until `fedsim command restore
  /// control_loading` (a loader does not re-engage on its own).
  double tick_watchdog_periods() const override { return kTickWatchdogPeriods; }
  void on_ticks_stopped(const runtime::FrameContext& last, double silent_s) override;
  static constexpr double kTickWatchdogPeriods = timing::TickGapWatch::Limits{}.late_periods;
  /// Late ticks ridden through so far.
  std::uint64_t late_ticks() const { return tick_gaps_.late_ticks(); }

  const ControlLoading& loader() const { return loader_; }

 private:
  void take_inputs(const runtime::FrameContext& frame);
  void report_status_change(const runtime::FrameContext& frame);

  // ---- Ports -------------------------------------------------------------------------------
  // reads  fedsim/aircraft_state: lockstep input (air.qbar_pa, air.alpha_rad, stamp).
  runtime::Input<msg::AircraftState>& aircraft_state_;
  // reads  fedsim/pilot_controls: lockstep input (elevator, aileron, rudder and their trims).
  runtime::Input<msg::PilotControls>& pilot_controls_;
  // monitors fedsim/autopilot_state: the back-drive commands (never holds the frame back).
  runtime::Input<msg::AutopilotState>& autopilot_state_;
  // writes fedsim/control_loading_state every frame (catalogue default, or --state-qos).
  runtime::Output<msg::ControlLoadingState>& control_loading_state_;

  ControlLoadingSetup setup_;
  ControlLoading loader_;
  ControlLoadingInputs inputs_;
  bool have_inputs_ = false;
  std::uint64_t aircraft_seen_ = 0;
  static constexpr int kAutopilotStaleFrames = 3;  // an autopilot state this old no longer drives
  std::uint64_t autopilot_seen_ = 0;
  int autopilot_stale_frames_ = kAutopilotStaleFrames;
  bool engage_wanted_ = false;
  bool instructor_cut_ = false;
  LoaderStatus last_status_ = LoaderStatus::kSafe;
  timing::TickGapWatch tick_gaps_;  // late ticks ridden through, stops, bursts
  msg::ControlLoadingState sample_;
};

/// fedsim-control-loading as a program: --engage on|off, --aircraft (the shaker from the pack),
/// --state-qos.
runtime::FederateProgram program();

}  // namespace fedsim::control_loading
