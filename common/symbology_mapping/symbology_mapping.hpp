// What the cockpit symbology is given from the federation's state topics, where both image
// federates need it: pure functions from the IDL samples (fedsim/aircraft_state,
// fedsim/navigation_state, fedsim/autopilot_state) to common/symbology's and common/hud's inputs,
// and the magnetic variation the headings are shown with. fedsim-displays maps its PFD and ND on
// top of these (federates/displays/display_mapping.hpp); fedsim-visual --hud draws the HUD from
// hud_inputs(). No DDS entity, no clock: tested directly (federates/displays/test/
// display_mapping_test.cpp and the image generator's HUD test).
#pragma once

#include "common/hud/hud_inputs.hpp"
#include "common/navdb/nav_database.hpp"
#include "common/symbology/flight_director.hpp"
#include "fedsim/msg/aircraft_state.h"
#include "fedsim/msg/autopilot.h"
#include "fedsim/msg/navigation.h"

#include <vector>

namespace fedsim::symbology_mapping {

/// The local magnetic variation [rad] (east +) the headings are shown with; the adapters take it
/// from the nearest navaid in the navigation database.
struct DisplayContext {
  double magnetic_variation_rad = 0.0;
};

/// The variation of the nearest of `hits` (NavDatabase::within(), nearest first); 0 when none.
double magnetic_variation_of_nearest(const std::vector<nav::NavaidHit>& hits);
/// The variation of the nearest navaid within `range_nm` of the position (0 when none).
double magnetic_variation_near(const nav::NavDatabase& db, double lat_rad, double lon_rad, double range_nm);

/// An angle in [0, 2 pi) [rad].
double wrap_2pi(double angle_rad);

/// Flight director bars: the autopilot's when it has one (its FD switch, or CMD), else the
/// navigation federate's own FD computer (idl/navigation.idl FlightDirectorState) when a mode is
/// active; off when neither. `nav`, `autopilot` may be null (not yet received).
symbology::FlightDirector flight_director(const msg::NavigationState* nav, const msg::AutopilotState* autopilot);

/// HUD inputs: attitude, true heading, velocity over the ground (the FPV), speed, altitude,
/// vertical speed, the FD cue.
hud::HudInputs hud_inputs(const msg::AircraftState& state, const msg::NavigationState* nav,
                          const msg::AutopilotState* autopilot, const DisplayContext& context);

}  // namespace fedsim::symbology_mapping
