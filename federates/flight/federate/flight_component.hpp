// fedsim-flight's adapter (the seed's node 2): steps the aircraft model once per frame from the
// pilot controls and writes the aircraft and engine state.
//
// Run states: RUN integrates one frame period; FREEZE holds the aircraft and keeps writing;
// RESET returns to the start state. Commands: reposition (point, runway threshold, approach
// gate), weather, failures (engine1..4, autopilot, autothrottle). Faults (counted, in the
// federate status and the summary): "numerical" - the model dropped a step that would have
// produced a non-finite state; pilot-controls samples refused by the input gate
// (pilot_input_gate.hpp; the last good input is kept): "controls_other_aircraft",
// "controls_not_finite", "controls_out_of_range", "controls_bad_stamp"; "input_rejected" - a bad MCP panel (the previous one is kept), or bad force-sensor
// readings (non-finite or beyond 2000 N: the previous CWS inputs are kept). A writer that stops
// writing costs at most the runtime's input timeout per frame: the last good input is flown,
// held (logged when it starts and ends, frames counted in the stop summary). A second writer of
// fedsim/pilot_controls (exclusive ownership: the strongest flies, e.g. a trainer taking over)
// is a warning, "controls_second_writer", counted in the stop summary, not a fault.
//
// Writes fedsim/applied_controls every frame: the controls the model flew in that frame (after
// the gate, relative-mode trim and the autopilot), so that a recording holds exactly what was
// flown whatever the input topic carried (a flood, refused samples, a second writer).
//
// With the autopilot hosted (--autopilot, model/afcs/README.md "Where the AFCS runs"), each RUN
// frame, after the pilot's controls are set and before the model steps: the AFCS reads the
// aircraft (the model's outputs), NAV1's ILS readings (fedsim/navigation_state of frame N-1),
// the MCP (the panel in fedsim/pilot_controls) and the control-wheel steering inputs (the
// column and wheel forces of pilot_force_n, with DISCRETE_FORCE_SENSORS; hands off without),
// steps, and its engaged channels replace the pilot's; every mode change is logged; fedsim/autopilot_state carries the FMA every frame.
#pragma once

#include "flight/federate/replay_playback.hpp"

#include "common/airports/runway_centreline.hpp"
#include "common/airports/runway_table.hpp"
#include "common/runtime/component.hpp"
#include "flight/federate/autopilot_adapter.hpp"
#include "flight/federate/flight_adapter.hpp"
#include "flight/federate/pilot_input_gate.hpp"
#include "flight/federate/start_options.hpp"
#include "flight/model/afcs/approach_progress.hpp"
#include "flight/model/afcs/model_coupling.hpp"

#include <memory>

namespace fedsim::flight {

/// Everything the flight component flies, prepared (and checked) before it joins.
struct FlightSetup {
  std::unique_ptr<AircraftModel> model;
  StartState start;
  RunwayTable runways;
  ControlsMode controls_mode = ControlsMode::kAbsolute;
  int aircraft_id = 0;
  /// Host the AFCS (autopilot, flight director, autothrottle) with these parameters.
  std::optional<afcs::AfcsParameters> autopilot;
  /// The runway the progress note measures the distance to go to (--airport/--runway starts).
  std::optional<RunwayCentreline> progress_runway;
};

class FlightComponent final : public runtime::Component {
 public:
  /// `state_qos` overrides the catalogue's profile of fedsim/aircraft_state.
  FlightComponent(std::string name, FlightSetup setup, std::string_view state_qos = {});

  void on_command(const msg::SimCommand& command) override;
  void step(const runtime::FrameContext& frame) override;
  void on_stop() override;
  /// Phase of flight, distance to go, height, speed and the FMA (approach_progress.hpp).
  std::string progress_note() const override;

  const AircraftModel& model() const { return *setup_.model; }
  /// The hosted AFCS (nullptr without --autopilot, or before the first RUN frame).
  const afcs::Afcs* autopilot() const { return afcs_.get(); }
  /// The pilot-controls gate (what was flown, refused, held).
  const PilotInputGate& input_gate() const { return gate_; }

 private:
  /// Every frame: a new pilot-controls sample through the gate (refusals counted by kind), the
  /// writers counted (a second one warned of), the hold watched.
  void take_pilot_controls(const runtime::FrameContext& frame);
  void watch_controls_writers(const runtime::FrameContext& frame);
  /// Reports what the screen kept from the port since the last frame (by kind, per sample).
  void report_screened_controls(const runtime::FrameContext& frame);
  /// RUN frames: the last good input to the model.
  void apply_pilot_controls(const runtime::FrameContext& frame);
  /// The pilot's wing-leveller switch (discrete bit) to the pack's wing leveller, logged on change.
  void apply_wing_leveller_switch(const runtime::FrameContext& frame);
  void take_mcp(const runtime::FrameContext& frame);
  /// The control-wheel steering inputs from the force sensors of a new pilot-controls sample
  /// (hands off without DISCRETE_FORCE_SENSORS); bad readings are rejected and counted
  /// ("input_rejected"), the previous inputs kept.
  void take_pilot_forces(const runtime::FrameContext& frame);
  void fly_autopilot(const runtime::FrameContext& frame);
  afcs::AfcsIlsSignals nav1_ils() const;
  void log_transition(const afcs::ModeTransition& t);
  bool apply_autopilot_failure(const msg::SimCommand& command);
  void write_state(const runtime::FrameContext& frame);
  /// The replay: true while it drives the aircraft state this frame (the model waits);
  /// takes control from its last sample when it ends.
  bool follow_replay(const runtime::FrameContext& frame);

  // ---- Ports -------------------------------------------------------------------------------
  // reads  fedsim/pilot_controls: lockstep input, frame N flies the controls of frame N-1.
  runtime::Input<msg::PilotControls>& pilot_controls_;
  // writes fedsim/applied_controls every frame: the controls the model flew (as the state).
  runtime::Output<msg::PilotControls>& applied_controls_;
  // writes fedsim/aircraft_state every frame (catalogue default "state", or --state-qos).
  runtime::Output<msg::AircraftState>& aircraft_state_;
  // writes fedsim/engine_state every frame, one sample (instance) per engine.
  runtime::Output<msg::EngineState>& engine_state_;
  // reads  fedsim/replay_state (a monitor): a replay's aircraft states, written as this
  //        federate's own while they arrive (replay_playback.hpp).
  runtime::Input<msg::AircraftState>& replay_state_;
  // With the autopilot only (nullptr otherwise):
  // reads  fedsim/navigation_state: lockstep input, NAV1's ILS readings of frame N-1.
  runtime::Input<msg::NavigationState>* navigation_state_ = nullptr;
  // writes fedsim/autopilot_state every frame (the FMA, FD bars, AFCS commands).
  runtime::Output<msg::AutopilotState>* autopilot_state_ = nullptr;

  FlightSetup setup_;
  AircraftControls trim_base_;  // relative controls fly about the latest trim
  std::uint64_t controls_seen_ = 0;       // pilot_controls_.updates() last checked
  std::uint64_t controls_accepted_ = 0;   // pilot_controls_.updates() of the last sample the gate took
  PilotInputGate gate_;
  PilotInputScreen screen_;               // where samples arrive (Input::accept_only)
  std::uint64_t screened_other_ = 0;      // screen_ counts already reported
  std::uint64_t screened_future_ = 0;
  msg::PilotControls applied_;            // fedsim/applied_controls sample (reused)
  bool pilot_inputs_invalid_ = false;     // the I/O federate marks its samples invalid (device lost)
  std::uint64_t dropped_steps_seen_ = 0;
  msg::AircraftState state_;
  msg::EngineState engine_;
  ReplayPlayback playback_;

  // The hosted AFCS (built in the first RUN frame, at the federation's frame period).
  std::unique_ptr<afcs::Afcs> afcs_;
  double afcs_dt_s_ = 0.0;
  afcs::GearGeometry gear_;
  McpPressTracker mcp_presses_;
  std::uint64_t mcp_seen_ = 0;           // pilot_controls_.updates() when the MCP was last read
  afcs::McpButtons pending_presses_;     // seen in a sample, pressed in the next RUN frame
  msg::McpPanel last_valid_mcp_;
  bool have_valid_mcp_ = false;
  std::uint64_t forces_seen_ = 0;        // pilot_controls_.updates() when the forces were last read
  CwsInputs cws_;                        // the pilot's column and wheel forces as CWS inputs
  afcs::AfcsFailures afcs_failures_;
  std::uint32_t transitions_ = 0;
  msg::AutopilotState autopilot_sample_;
};

}  // namespace fedsim::flight
