// What the cockpit displays are given, from the federation's state topics: pure functions from
// the IDL samples (fedsim/aircraft_state, fedsim/navigation_state, fedsim/autopilot_state) to
// the displays model's inputs (model/display_inputs.hpp), on top of what fedsim-visual's HUD
// shares (common/symbology_mapping: the flight director, the magnetic variation). No DDS entity,
// no clock: tested directly (test/display_mapping_test.cpp).
//
// Conventions (the IDL's and the model's, both SI): a NAV receiver's deviations are -1..1 of full
// scale, + fly right / fly up; the displays' scales are 2 dots each side, so dots = 2 x deviation.
// A reading that is not valid is never drawn as a pointer: a receiver tuned to a station that
// is not usable shows the flag (NavSignal::kFailed); one with nothing of that kind tuned, none.
#pragma once

#include "common/navdb/nav_database.hpp"
#include "common/symbology_mapping/symbology_mapping.hpp"
#include "displays/model/display_inputs.hpp"
#include "fedsim/msg/aircraft_state.h"
#include "fedsim/msg/autopilot.h"
#include "fedsim/msg/navigation.h"

#include <string>
#include <vector>

namespace fedsim::displays {

/// Dots of a display's deviation scale (2 dots full scale) for a deflection of -1..1 of full
/// scale (NavReceiver::course_deviation, glideslope_deviation); clamped to the scale's +-2.5.
double deviation_dots(double full_scale_fraction);

/// True for an ILS localizer channel: 108.10-111.95 MHz with an odd tenth of a MHz (ICAO Annex
/// 10 Vol I 3.1.3.2.1), so a receiver tuned to one and receiving nothing shows a LOC flag.
bool is_localizer_frequency(std::uint32_t frequency_khz);

/// The localizer as the PFD shows it: kValid when a localizer is received and valid, kFailed
/// when the receiver is tuned to a localizer (by its signal or frequency) that is not usable,
/// kNotTuned otherwise (a VOR, or nothing tuned).
NavSignal localizer_signal(const msg::NavReceiver& nav);
/// The glide slope paired with the localizer: kValid / kFailed as the localizer's rule, and
/// kNotTuned whenever the localizer is not tuned.
NavSignal glideslope_signal(const msg::NavReceiver& nav);
/// The course signal as the ND / HSI shows it (a VOR or a localizer).
NavSignal course_signal(const msg::NavReceiver& nav);

MarkerBeacon marker_of(msg::MarkerBeaconKind kind);
ToFrom to_from_of(msg::ToFromFlag flag);

/// The FMA's text (Boeing abbreviations, idl/autopilot.idl), "" for none.
FlightModes flight_modes(const msg::FlightModeAnnunciator& fma);
/// PFD inputs: attitude, speeds, altitude (MSL, altimeter set to the standard 1013.25 hPa, as
/// the standard atmosphere of the flight model makes MSL and indicated altitude one), trends
/// (IAS in 10 s from the along-body acceleration, altitude in 6 s from the climb rate), radio
/// altitude (height of the CG above the terrain), NAV1 localizer and glide slope, marker, FD
/// and the FMA. `nav`, `autopilot` may be null (not yet received: nothing tuned, no FD).
PfdInputs pfd_inputs(const msg::AircraftState& state, const msg::NavigationState* nav,
                     const msg::AutopilotState* autopilot, const symbology_mapping::DisplayContext& context);

/// ND inputs: heading and track up (magnetic), NAV1's course, deviation, TO/FROM and DME,
/// bearing pointer 1 to the VOR on NAV2 (the VOR on NAV1 when NAV2 has none), bearing pointer 2
/// to the ADF's NDB, the navaids given, GS and TAS.
NdInputs nd_inputs(const msg::AircraftState& state, const msg::NavigationState* nav,
                   const symbology_mapping::DisplayContext& context, std::vector<Navaid> navaids, double range_nm);

/// The ND's navaids from the database: those within range_nm of the position, at their
/// magnetic bearing (true bearing - variation) and distance, nearest first, at most `limit`;
/// and the variation at the nearest navaid (0 when none is within range).
struct NearbyNavaids {
  std::vector<Navaid> navaids;
  double magnetic_variation_rad = 0.0;
};
NearbyNavaids nearby_navaids(const nav::NavDatabase& db, double lat_rad, double lon_rad, double range_nm,
                             std::size_t limit = 40);

/// The aircraft state's fields the displays draw, checked: "" when usable, else the first field
/// that is not finite or out of range (named), so that the adapter reports it and keeps the
/// last picture.
std::string aircraft_state_problem(const msg::AircraftState& state);

}  // namespace fedsim::displays
