// fedsim-flight's adapter (the seed's node 2): steps the aircraft model once per frame from the
// pilot controls and writes the aircraft and engine state.
//
// Run states: RUN integrates one frame period; FREEZE holds the aircraft and keeps writing;
// RESET returns to the start state. Commands: reposition (point, runway threshold, approach
// gate), weather, engine failures. Faults (counted, in the federate status and the summary):
// "numerical" - the model dropped a step that would have produced a non-finite state;
// "input_rejected" - a pilot-controls sample with a non-finite or out-of-range value (the
// previous controls are kept).
#pragma once

#include "common/airports/runway_table.hpp"
#include "common/runtime/component.hpp"
#include "flight/federate/flight_adapter.hpp"
#include "flight/federate/start_options.hpp"

#include <memory>

namespace fedsim::flight {

/// Everything the flight component flies, prepared (and checked) before it joins.
struct FlightSetup {
  std::unique_ptr<AircraftModel> model;
  StartState start;
  RunwayTable runways;
  ControlsMode controls_mode = ControlsMode::kAbsolute;
  int aircraft_id = 0;
};

class FlightComponent final : public runtime::Component {
 public:
  /// `state_qos` overrides the catalogue's profile of fedsim/aircraft_state.
  FlightComponent(std::string name, FlightSetup setup, std::string_view state_qos = {});

  void on_command(const msg::SimCommand& command) override;
  void step(const runtime::FrameContext& frame) override;

  const AircraftModel& model() const { return *setup_.model; }

 private:
  void apply_pilot_controls(const runtime::FrameContext& frame);
  void write_state(const runtime::FrameContext& frame);

  // ---- Ports -------------------------------------------------------------------------------
  // reads  fedsim/pilot_controls: lockstep input, frame N flies the controls of frame N-1.
  runtime::Input<msg::PilotControls>& pilot_controls_;
  // writes fedsim/aircraft_state every frame (catalogue default "state", or --state-qos).
  runtime::Output<msg::AircraftState>& aircraft_state_;
  // writes fedsim/engine_state every frame, one sample (instance) per engine.
  runtime::Output<msg::EngineState>& engine_state_;

  FlightSetup setup_;
  AircraftControls trim_base_;  // relative controls fly about the latest trim
  std::uint64_t controls_seen_ = 0;       // pilot_controls_.updates() last checked
  msg::PilotControls last_valid_controls_;
  bool have_valid_controls_ = false;
  std::uint64_t dropped_steps_seen_ = 0;
  msg::AircraftState state_;
  msg::EngineState engine_;
};

}  // namespace fedsim::flight
