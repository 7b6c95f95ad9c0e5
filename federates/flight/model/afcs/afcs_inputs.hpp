// What the AFCS reads every frame (Drake-style port list). SI, angles in radians, true
// directions; + conventions of docs/frames.md (bank + right wing down, pitch + nose up, heading
// and track clockwise from true north, vertical speed + up).
//
//   aircraft  - the flight model's state (AircraftOutputs through model_coupling.hpp, or the
//               aircraft-state topic in a federation) and the pilot's present control commands
//               (for bumpless engagement);
//   ils       - the NAV1 receiver's readings (common/radio) with their validity: the localizer and
//               glide slope of an ILS, or (ils.vor) a VOR with its DME; a flagged signal is
//               never flown;
//   mcp       - the mode control panel: selections (held values) and buttons (true in the frame
//               the button is pressed: edges, as the I/O federate's discretes arrive).
// Every number is checked each frame (afcs_input_problem()): a bad sample disengages the
// autopilot with an alert rather than reaching a control law.
#pragma once

#include "common/units/units.hpp"

#include <cstdint>
#include <string_view>

namespace fedsim::flight::afcs {

struct AfcsAircraftState {
  double time_s = 0.0;               // simulation time [s]
  double roll_rad = 0.0;             // phi, + right wing down [rad], [-pi, pi]
  double pitch_rad = 0.0;            // theta, + nose up [rad], [-pi/2, pi/2]
  double heading_true_rad = 0.0;     // psi [rad], any finite (wrapped)
  double roll_rate_radps = 0.0;      // p, body axes, relative to the earth [rad/s]
  double pitch_rate_radps = 0.0;     // q [rad/s]
  double yaw_rate_radps = 0.0;       // r [rad/s]
  double calibrated_airspeed_mps = 0.0;  // CAS [m/s], [0, 400]
  double true_airspeed_mps = 0.0;    // TAS [m/s], [0, 400]
  double ground_speed_mps = 0.0;     // horizontal speed over the ground [m/s], [0, 400]
  double track_true_rad = 0.0;       // direction of the ground velocity [rad] (heading when slow)
  double altitude_m = 0.0;           // altimeter altitude above MSL [m], [-1000, 20000]
  double vertical_speed_mps = 0.0;   // + up [m/s], [-150, 150]
  double radio_height_m = 0.0;       // main-gear height above the runway [m], [-10, 10000]
  double angle_of_attack_rad = 0.0;  // alpha [rad], [-pi, pi] (meaningless at taxi speed)
  double sideslip_rad = 0.0;         // beta, + wind from the right [rad], [-pi/2, pi/2]
  double lateral_specific_force_mps2 = 0.0;  // accelerometer, body y, + right [m/s^2], [-50, 50]
  double longitudinal_acceleration_mps2 = 0.0;  // d(ground speed)/dt along the track [m/s^2]
  bool main_gear_on_ground = false;  // a main wheel carries load
  bool nose_gear_on_ground = false;  // the nose wheel carries load
  // The pilot's present commands (AircraftControls' normalised units): the AFCS engages from
  // them without a bump.
  double elevator = 0.0;  // -1..1, + nose down
  double aileron = 0.0;   // -1..1, + right wing down
  double rudder = 0.0;    // -1..1, + nose right
  double throttle = 0.0;  // 0..1 (the levers; all engines together)
  double pitch_trim = 0.0;  // the pitch trim's present position, -1..1 in the elevator's sense
};

/// The VOR's TO/FROM flag (common/radio ToFrom, navigation.idl ToFromFlag).
enum class VorToFrom : std::uint8_t { kOff, kTo, kFrom };

/// NAV1 tuned to a VOR (then the localizer and glide slope of AfcsIlsSignals read flagged).
struct AfcsVorSignals {
  bool tuned = false;              // NAV1's course signal is a VOR, valid or flagged
  bool valid = false;              // false: flagged (the numbers below, DME apart, are ignored)
  bool cone_of_confusion = false;  // flagged because overhead the station (the receiver says so)
  double deviation = 0.0;          // CDI, -1..1 of full scale, + = fly right [-]
  double full_scale_rad = 10.0 * units::kDegToRad;  // angle off course at full scale, (0, 20 deg]
  double course_true_rad = 0.0;    // the selected course (OBS) converted to true [rad]
  VorToFrom to_from = VorToFrom::kOff;
  bool dme_valid = false;          // the DME paired with the VOR's frequency is received
  double dme_slant_range_m = 0.0;  // [m], [0, 500 km] when valid
};

struct AfcsIlsSignals {
  bool localizer_valid = false;        // false: flagged (numbers below ignored)
  double localizer_deviation = 0.0;    // -1..1 of full scale, + = fly right [-]
  double localizer_half_width_rad = 0.0;  // angle off course at full scale [rad], (0, 0.2]
  double localizer_course_true_rad = 0.0;  // inbound front course [rad]
  double localizer_distance_m = 0.0;   // from the localizer antenna [m], [0, 100 km]
  bool glide_slope_valid = false;
  double glide_slope_deviation = 0.0;  // -1..1 of full scale, + = fly up [-]
  double glide_path_angle_rad = 0.0;   // theta_gs [rad], [0.5 deg, 10 deg] when valid
  double glide_slope_distance_m = 0.0; // from the glide-slope antenna [m], [0, 100 km]
  double distance_to_threshold_m = 0.0;  // along the course, + before the threshold [m]
  // NAV1 is one receiver: the federate passes its reading here whether it holds a localizer or
  // a VOR (autopilot_adapter ils_signals_from_receiver), the batch runs the same (model_coupling).
  AfcsVorSignals vor;
};

/// Mode-control-panel buttons: true in the frame the button is pressed.
struct McpButtons {
  bool autopilot_engage = false;       // "CMD"
  bool control_wheel_steering = false; // "CWS": engage in attitude hold
  bool autopilot_disconnect = false;   // yoke disconnect switch (second press: silence alert)
  bool autothrottle_disconnect = false;  // thrust-lever disconnect switch
  bool heading_select = false;         // "HDG SEL"
  bool wing_level = false;             // "WLV" (a wing-leveller button, the C172's)
  bool vor_localizer = false;          // "VOR LOC": arm (press again: disarm)
  bool approach = false;               // "APP": arm LOC and G/S (press again: disarm)
  bool altitude_hold = false;          // "ALT HLD": hold the present altitude
  bool vertical_speed = false;         // "V/S"
  bool level_change = false;           // "LVL CHG"
  bool speed = false;                  // "SPEED": autothrottle speed mode
  bool thrust = false;                 // "N1": autothrottle climb thrust
  bool takeoff_go_around = false;      // "TO/GA" on the thrust levers
};

/// Every button pressed in either (presses gathered over frames).
McpButtons& operator|=(McpButtons& a, const McpButtons& b);

/// Mode-control-panel selections (held values).
struct McpSelections {
  double heading_true_rad = 0.0;       // [rad], any finite (wrapped)
  double altitude_m = 0.0;             // MSL [m], [-1000, 20000]
  double vertical_speed_mps = 0.0;     // + up [m/s], [-40, 40]
  double calibrated_airspeed_mps = 0.0;  // [m/s], [40, 200]
  double bank_limit_rad = 0.436;       // heading-select bank limit [rad], [0.087, 0.524] (5-30 deg)
  bool flight_director_on = true;      // FD switch: modes also compute for the FD bars
  bool autothrottle_armed = false;     // A/T ARM switch (off: autothrottle off)
  int autobrake_setting = 2;           // 0 off, 1, 2, 3, 4 = MAX
  double pilot_pitch_input = 0.0;      // CWS column force, -1..1, + nose up (0: hands off)
  double pilot_roll_input = 0.0;       // CWS wheel force, -1..1, + right (0: hands off)
};

/// Failures the instructor sets: a failed autopilot (autothrottle) disengages with its alert and
/// refuses engagement until restored.
struct AfcsFailures {
  bool autopilot = false;
  bool autothrottle = false;
};

struct AfcsInputs {
  AfcsAircraftState aircraft;
  AfcsIlsSignals ils;
  McpButtons buttons;
  McpSelections mcp;
  AfcsFailures failures;
};

/// The first field of `inputs` that is not finite or outside its stated range, named as
/// "aircraft.calibrated_airspeed_mps" (an ILS field only while its signal is valid); empty
/// when the inputs are fine.
std::string_view afcs_input_problem(const AfcsInputs& inputs);

}  // namespace fedsim::flight::afcs
