// fedsim-nav's adapter (the seed's node 3, Section 2.11; Chapter 6): every frame it reads the
// aircraft state of the previous frame and the pilot's radio tuning, steps the avionics suite
// (model/avionics: NAV1/NAV2 VOR-ILS-DME, ADF, markers, GPS, INS, flight director over the
// navigation database) and writes the navigation state.
//
// Tuning: the latest change wins, whoever made it: the pilot (the RadioTuning of
// fedsim/pilot_controls: a radio whose field changes is retuned; 0 kHz leaves it as it is), the
// instructor (COMMAND_RADIO_TUNING) or the start options (--nav1-mhz ...).
// Failures (COMMAND_FAILURE, target): nav1, nav2, adf, markers, ins, gps (denied), and a ground
// station off the air: station:<IDENT> (everything), station-dme:<IDENT>, station-gs:<IDENT>,
// station-markers:<IDENT>. Each makes the readings invalid (flagged), never wrong.
// Reset and reposition realign the INS on the next state. Faults (federate status, summary,
// exit status): "input_rejected" - an aircraft-state sample with a non-finite or out-of-range
// value (the previous one is kept).
#pragma once

#include "common/navdb/nav_database.hpp"
#include "common/runtime/component.hpp"
#include "common/runtime/federate_main.hpp"
#include "nav/model/avionics/avionics_suite.hpp"
#include "nav/model/avionics/database_station_source.hpp"

#include <memory>
#include <optional>

namespace fedsim::nav {

/// Everything the component needs, prepared (and checked) before it joins.
struct NavSetup {
  std::unique_ptr<NavDatabase> database;
  AvionicsConfig config;
  RadioSelections initial_radios;
  int aircraft_id = 0;
  std::string state_qos;  // profile of fedsim/navigation_state ("" = the catalogue's)
};

/// The avionics truth of an aircraft-state sample, or the reason it cannot be used.
std::optional<std::string> truth_from_message(const msg::AircraftState& s, AvionicsTruth& out);
/// The navigation-state message of a set of readings (no allocation).
void to_message(const AvionicsReadings& r, const RadioSelections& radios, bool gps_denied,
                msg::NavigationState& out);

class NavComponent final : public runtime::Component {
 public:
  explicit NavComponent(std::string name, NavSetup setup);

  void on_command(const msg::SimCommand& command) override;
  void step(const runtime::FrameContext& frame) override;

  const AvionicsSuite& suite() const { return *suite_; }

 private:
  void apply_pilot_tuning();
  bool take_aircraft_state(const runtime::FrameContext& frame);
  void apply_failure(const std::string& target, bool active);

  // ---- Ports -------------------------------------------------------------------------------
  // reads  fedsim/aircraft_state: lockstep input, frame N navigates on the state of frame N-1.
  runtime::Input<msg::AircraftState>& aircraft_state_;
  // reads  fedsim/pilot_controls: lockstep input, the radio tuning.
  runtime::Input<msg::PilotControls>& pilot_controls_;
  // writes fedsim/navigation_state every frame (catalogue default "state": best effort).
  runtime::Output<msg::NavigationState>& navigation_state_;

  NavSetup setup_;
  std::unique_ptr<DatabaseStationSource> stations_;
  std::unique_ptr<AvionicsSuite> suite_;
  std::uint64_t state_updates_seen_ = 0;
  std::uint64_t controls_updates_seen_ = 0;
  msg::RadioTuning last_pilot_tuning_;  // the pilot's last tuning seen (changes retune)
  AvionicsTruth truth_;
  bool have_truth_ = false;
  double truth_time_s_ = 0.0;           // sim time of truth_ [s]
  bool realign_requested_ = false;      // a reposition arrived
  std::uint64_t realign_at_frame_ = 0;  // realign the INS on the state read in that frame
  msg::NavigationState sample_;
};

/// fedsim-nav as a program: --db, --nav1-mhz, --nav2-mhz, --obs1-deg, --obs2-deg, --adf-khz,
/// --ins-grade, --seed, --gps-time-s, --state-qos, --aircraft-id.
runtime::FederateProgram program();

}  // namespace fedsim::nav
