// The flight federate's translation layer between topics and the flight model (no DDS calls):
// pilot controls in, aircraft and engine state out, instructor commands applied to the model.
#pragma once

#include "fedsim/msg/aircraft_state.h"
#include "fedsim/msg/command.h"
#include "fedsim/msg/controls.h"
#include "flight/model/aircraft/aircraft_model.hpp"
#include "flight/model/scenario/reposition.hpp"
#include "common/airports/runway_table.hpp"

#include <optional>
#include <string>

namespace fedsim::flight {

/// How pilot controls from the topic are applied.
///   absolute - they are the inceptor positions;
///   relative - elevator, aileron, rudder and throttles are ADDED to the trimmed values (a
///              scripted profile of doublets flies about the trim); the other channels
///              (flaps, gear, brakes, steering, mixture, propeller, trims) are absolute.
enum class ControlsMode { kAbsolute, kRelative };

// Whether a pilot-controls sample may be flown: pilot_input_gate.hpp.

/// Pilot controls as the model takes them (clamped by the model).
AircraftControls controls_from_message(const msg::PilotControls& in, ControlsMode mode,
                                       const AircraftControls& trimmed);

/// Fills a fedsim/applied_controls sample: the controls the model flies (`flown`, after
/// relative-mode trim and the autopilot), with the discretes, radios and MCP of the input they
/// came from (`source`, nullptr before a first good input: zeros). The stamp is the caller's.
void fill_applied_controls(const AircraftControls& flown, const msg::PilotControls* source,
                           msg::PilotControls& out);

/// Fills an AircraftState sample from the model's outputs and the controls it flew (no
/// allocation). Every field of the message is set (tested).
void fill_aircraft_state(const AircraftOutputs& out, const AircraftControls& flown,
                         msg::AircraftState& state);
/// Fills one engine's EngineState sample.
void fill_engine_state(const EngineOutputs& engine, std::size_t index, msg::EngineState& state);

/// Weather settings from an instructor command. The wind is `wind_speed_mps` from
/// `wind_from_rad` at the surface (runway elevation), increasing by the gradient up to 600 m
/// above it and constant higher up.
WeatherSettings weather_from_command(const msg::WeatherSettings& in, double surface_elevation_m);

/// Applies a reposition / weather / failure command to the model; returns a one-line summary
/// for the log, or throws std::invalid_argument with a reason (unknown runway, bad target).
std::string apply_command(const msg::SimCommand& command, AircraftModel& model,
                          const RunwayTable& runways);

}  // namespace fedsim::flight
