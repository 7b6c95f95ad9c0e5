// The AFCS mode logic: an explicit state machine over the engagement status, the active and
// armed roll and pitch modes and the thrust mode (the FMA), driven by the mode-control-panel
// buttons and by conditions the guidance evaluates each frame (capture points reached, signals
// valid, heights crossed). It computes no control law.
//
// Every change of a mode, an armed mode or an engagement is reported once, in the order it
// happens, to the transition callback (the adapter publishes or logs it; tests record it).
// The rules follow the 737's AFDS as described in the FCOM (Boeing 737 Flight Crew Operations
// Manual, "Automatic Flight" chapter), simplified where the notes in README.md say so:
//  - engagement: CMD engages when airborne, inputs valid and the attitude within +-30 deg bank,
//    -10..+20 deg pitch; with no roll mode it engages in HDG HOLD (bank < 6 deg) or CWS R, with
//    no pitch mode in CWS P. The disconnect switch disengages with the AP warning latched until
//    pressed again;
//  - failures (instructor): a failed autopilot or autothrottle disengages with its alert and
//    refuses engagement until restored;
//  - protections: a non-finite input sample, a flagged localizer while VOR/LOC, ALIGN or ROLLOUT
//    is active, a flagged glide slope while G/S is active, or an attitude beyond +-45 deg bank /
//    -15..+25 deg pitch disengage the autopilot (and, for a bad input sample, the autothrottle)
//    with an alert; the flagged mode reverts to HDG HOLD / CWS P for the flight director;
//  - after G/S capture only TO/GA (or disengagement) leaves the approach: other mode buttons and
//    a new MCP altitude are ignored and ALT ACQ is disarmed (no climb or descent to a newly
//    selected altitude on the glide slope);
//  - ALIGN, FLARE and ROLLOUT need the autopilot engaged (no flight-director autoland);
//  - VOR/LOC flies what NAV1 receives: with a VOR tuned it captures the VOR's course (APP then
//    arms no glide slope) and keeps to it over the station: on the cone-of-confusion flag, an
//    erratic deviation or TO turning FROM it holds the course (the sub-mode "OVER STATION")
//    until VorGains::over_station_hold after the last of these, then tracks the course again;
//    any other flag, a flag outlasting max_over_station, or NAV1 no longer on a VOR disengages
//    with the VOR FLAG alert like a flagged localizer;
//  - a new MCP altitude during ALT ACQ returns to the mode it came from when the new altitude
//    still lies ahead, else levels off in ALT HOLD.
#pragma once

#include "flight/model/afcs/afcs_inputs.hpp"
#include "flight/model/afcs/afcs_modes.hpp"
#include "flight/model/afcs/afcs_outputs.hpp"
#include "flight/model/afcs/afcs_parameters.hpp"

#include <functional>
#include <string_view>

namespace fedsim::flight::afcs {

/// Conditions the guidance evaluates before the mode logic runs (one frame).
struct ModeConditions {
  bool inputs_valid = true;
  bool on_ground = false;            // a main wheel carries load
  bool stopped = false;              // on the ground below the taxi speed
  bool localizer_valid = false;
  bool glide_slope_valid = false;
  bool localizer_capture = false;    // the localizer capture point is reached
  bool glide_slope_capture = false;  // the glide-slope capture point is reached
  bool vor_tuned = false;            // NAV1's course signal is a VOR (valid or flagged)
  bool vor_valid = false;
  bool vor_cone_of_confusion = false;  // the VOR flagged overhead the station
  bool vor_capture = false;          // the VOR course's capture point is reached
  bool vor_station_passage = false;  // the deviation erratic, or TO turned FROM
  bool altitude_capture = false;     // the altitude-capture law should start
  bool altitude_captured = false;    // within the hold band of the MCP altitude
  bool selected_altitude_changed = false;
  bool selected_altitude_above = false;       // the MCP altitude lies above the aircraft
  bool selected_altitude_ahead = false;       // ... in the direction of the climb or descent
  bool below_flare_arm_height = false;        // radio height below the flare-arm height
  bool below_align_height = false;
  bool below_flare_height = false;
  bool below_retard_height = false;
  bool attitude_engage_limits = true;         // within the engagement limits
  bool attitude_authority_limits = true;      // within the disengagement limits
  bool wings_level = false;                   // |bank| < 6 deg: CMD engages in HDG HOLD
  bool autopilot_failed = false;              // by the instructor: disengage, refuse CMD/CWS
  bool autothrottle_failed = false;           // by the instructor: disengage, refuse the A/T
};

/// The mode state (what the FMA shows).
struct ModeState {
  bool autopilot_engaged = false;
  bool autothrottle_engaged = false;
  bool flight_director_on = false;
  LateralMode lateral = LateralMode::kNone;
  LateralArmed lateral_armed;
  VerticalMode vertical = VerticalMode::kNone;
  VerticalArmed vertical_armed;
  ThrustMode thrust = ThrustMode::kNone;
  std::uint32_t alerts = kAlertNone;
  bool vor = false;               // VOR/LOC captured a VOR (else the localizer)
  bool vor_over_station = false;  // ... and holds the course over the station
  friend bool operator==(const ModeState&, const ModeState&) = default;
};

/// One reported change.
struct ModeTransition {
  enum class Channel : std::uint8_t {
    kAutopilot,      // "OFF" <-> "CMD"
    kAutothrottle,   // "OFF" <-> "ARM"
    kFlightDirector, // "OFF" <-> "FD"
    kLateral,        // active roll mode
    kLateralArmed,   // an armed roll mode: from "" to the mode (armed) or back (disarmed)
    kVertical,
    kVerticalArmed,
    kThrust,
    kAlert,          // from "" to the alert's name (raised) or back (cleared)
    kLateralSubmode, // VOR/LOC's "OVER STATION" (from "" to it and back)
  };
  double time_s = 0.0;
  Channel channel = Channel::kLateral;
  std::string_view from;    // static strings: the callback may keep them
  std::string_view to;
  std::string_view reason;  // what caused it, e.g. "localizer capture point"
};

std::string_view to_string(ModeTransition::Channel channel);
/// The name of one alert bit ("AP DISCONNECT", ...).
std::string_view alert_name(AfcsAlert alert);

class ModeLogic {
 public:
  using TransitionCallback = std::function<void(const ModeTransition&)>;

  /// `on_transition` may be empty (no reporting); `vor`: the station passage's times.
  explicit ModeLogic(TransitionCallback on_transition = {}, const VorGains& vor = {});

  /// One frame: acknowledgements, protections, disconnects, engagement, buttons, then the
  /// automatic transitions, in that order. Returns the new state.
  const ModeState& update(double time_s, const McpButtons& buttons, const McpSelections& mcp,
                          const ModeConditions& conditions);

  const ModeState& state() const { return state_; }
  /// The mode ALT ACQ was entered from (to return to on a new MCP altitude).
  VerticalMode capture_entered_from() const { return capture_from_; }
  /// True in the frame the vertical mode became ALT HOLD by the ALT HLD button (hold the
  /// present altitude) rather than by a capture (hold the MCP altitude).
  bool altitude_hold_at_present_altitude() const { return hold_present_altitude_; }
  /// Back to everything off, alerts cleared (no transitions reported).
  void reset();

 private:
  bool modes_available() const { return state_.autopilot_engaged || state_.flight_director_on; }
  bool approach_locked() const;
  void acknowledge(const McpButtons& buttons);
  void protect(const ModeConditions& c);
  void disconnect(const McpButtons& buttons);
  void engage(const McpButtons& buttons, const ModeConditions& c);
  void flight_director(const McpSelections& mcp);
  void autothrottle_switch(const McpSelections& mcp, const ModeConditions& c);
  void protect_vor(const ModeConditions& c);
  void vor_flagged(std::string_view reason, const ModeConditions& c);
  void lateral_buttons(const McpButtons& buttons, const ModeConditions& c);
  void vertical_buttons(const McpButtons& buttons, const ModeConditions& c);
  void thrust_buttons(const McpButtons& buttons);
  void go_around(const McpButtons& buttons, const ModeConditions& c);
  void automatic_lateral(const ModeConditions& c);
  void automatic_vertical(const ModeConditions& c);
  void automatic_thrust(const ModeConditions& c);
  void clear_when_unavailable();

  void set_autopilot(bool engaged, std::string_view reason);
  void set_autothrottle(bool engaged, std::string_view reason);
  void set_lateral(LateralMode mode, std::string_view reason);
  void set_vertical(VerticalMode mode, std::string_view reason);
  void set_thrust(ThrustMode mode, std::string_view reason);
  void set_over_station(bool over, std::string_view reason);
  void arm_localizer(bool armed, std::string_view reason);
  void arm_rollout(bool armed, std::string_view reason);
  void arm_altitude_capture(bool armed, std::string_view reason);
  void arm_glide_slope(bool armed, std::string_view reason);
  void arm_flare(bool armed, std::string_view reason);
  void raise(AfcsAlert alert, std::string_view reason);
  void clear_alert(AfcsAlert alert, std::string_view reason);
  void report(ModeTransition::Channel channel, std::string_view from, std::string_view to,
              std::string_view reason);
  void enter_climb_or_descent_thrust(bool climbing, std::string_view reason);

  TransitionCallback on_transition_;
  VorGains vor_gains_;
  ModeState state_;
  VerticalMode capture_from_ = VerticalMode::kNone;
  bool hold_present_altitude_ = false;
  bool autothrottle_tripped_ = false;  // disengaged: re-engages only after the switch is cycled
  double time_s_ = 0.0;
  double over_station_since_s_ = 0.0;  // OVER STATION entered
  double last_overhead_s_ = 0.0;       // the last cue of the station passage
};

}  // namespace fedsim::flight::afcs
