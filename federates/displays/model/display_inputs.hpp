// What the cockpit displays show, one plain struct per display (the HUD's is common/hud's), in
// SI units (docs/frames.md): angles in rad, speeds in m/s, heights in m, distances in m. Feet,
// knots, feet per minute and nautical miles appear only in the pictures (and in NdInputs::range_nm, the pilot's range
// selector, named so). The federate adapter fills these from the aircraft, navigation and
// autopilot states (idl/navigation.idl, idl/autopilot.idl); the model knows no DDS type.
//
// Signs: pitch + nose up, roll + right wing down, headings and bearings clockwise from north
// (magnetic unless named true), relative bearings clockwise from the nose. Localizer and course
// deviations in dots, + = fly right (the beam is right of the aircraft: the pointer is drawn
// right of centre); glide slope in dots, + = fly up (the beam is above: the pointer is drawn
// above centre). The displays' full scale is 2 dots (NavReceiver's -1..1 times 2).
//
// Navigation data that is not valid is drawn as an EFIS shows it: the pointer removed and a red
// flag in its place (NavSignal::kFailed), never as a pointer at a made-up place; a receiver
// not tuned to that kind of station shows neither scale nor flag (NavSignal::kNotTuned).
//
// validate_*() throws std::invalid_argument "<where>: field '<field>': <problem>" for a NaN, an
// infinity, a value out of its range or a string too long to draw (common/util/input_checks,
// common/symbology/input_checks).
#pragma once

#include "common/symbology/flight_director.hpp"

#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace fedsim::displays {

/// State of one navigation signal as a display treats it.
enum class NavSignal {
  kNotTuned,  // no station of that kind tuned: neither scale nor pointer nor flag
  kValid,     // scale and pointer
  kFailed,    // tuned but not usable (failed, off air, out of coverage): red flag, no pointer
};

enum class MarkerBeacon { kNone, kOuter, kMiddle, kInner };

/// The flight mode annunciator: three columns over the attitude indicator (Boeing order:
/// autothrottle, roll, pitch), each an active mode (green, upper line) and an armed one (white,
/// lower line); "" draws nothing. At most kFmaChars characters each.
struct FlightModes {
  std::string autothrottle_active;  // e.g. "MCP SPD", "N1", "RETARD"
  std::string autothrottle_armed;
  std::string roll_active;  // "HDG SEL", "VOR/LOC", "LNAV"
  std::string roll_armed;
  std::string pitch_active;  // "ALT HOLD", "G/S", "V/S"
  std::string pitch_armed;
  std::string afds_status;  // "CMD", "FD", "" (drawn above the aircraft symbol)
};
inline constexpr std::size_t kFmaChars = 10;

struct PfdInputs {
  double pitch_rad = 0.0;  // + nose up, -90..90 deg [rad]
  double roll_rad = 0.0;   // + right wing down, -180..180 deg [rad]
  // Lateral specific force along the body y axis (what a lateral accelerometer reads, + right)
  // [m/s^2]: the slip/skid indicator (the ball) moves opposite to it, full scale at 0.2 g.
  double lateral_specific_force_mps2 = 0.0;
  double heading_magnetic_rad = 0.0;    // [rad]
  double heading_true_rad = 0.0;        // [rad]
  bool heading_true_reference = false;  // show true heading ("TRU") instead of magnetic ("MAG")
  double ias_mps = 0.0;                 // indicated airspeed, 0..400 m/s [m/s]
  double ias_trend_mps = 0.0;       // speed predicted in 10 s minus now (the trend vector) [m/s]
  double altitude_m = 0.0;          // barometric altitude, -1000..20000 m [m] (drawn in ft)
  double altitude_trend_m = 0.0;    // altitude predicted in 6 s minus now [m]
  double vertical_speed_mps = 0.0;  // + climbing [m/s] (drawn in ft/min)
  std::optional<double> baro_setting_pa;      // altimeter setting; none: "STD" [Pa] (drawn in inHg)
  std::optional<double> selected_speed_mps;   // MCP speed (magenta bug and readout) [m/s]
  std::optional<double> selected_altitude_m;  // MCP altitude [m]
  std::optional<double> selected_heading_rad;  // MCP heading, magnetic [rad]
  NavSignal localizer = NavSignal::kNotTuned;
  double localizer_deviation_dots = 0.0;  // + fly right; clipped to the scale at +-2.5 [dots]
  NavSignal glideslope = NavSignal::kNotTuned;
  double glideslope_deviation_dots = 0.0;  // + fly up [dots]
  symbology::FlightDirector flight_director;  // common/symbology/flight_director.hpp
  FlightModes modes;
  std::optional<double> radio_altitude_m;  // radio altimeter; drawn at or below 2500 ft [m]
  MarkerBeacon marker = MarkerBeacon::kNone;
};

enum class ToFrom { kOff, kTo, kFrom };
enum class BearingSource { kVor, kAdf };
enum class NavaidKind { kVor, kVorDme, kDme, kNdb, kAirport };

/// One bearing pointer of the ND (pointer 1: single line, pointer 2: double line).
struct BearingPointer {
  BearingSource source = BearingSource::kVor;
  bool valid = false;                 // false: the pointer is removed, "---" beside its label
  double relative_bearing_rad = 0.0;  // to the station, clockwise from the nose [rad]
  std::string ident;                  // the station's identifier (<= 5 characters)
};

struct Navaid {
  std::string ident;  // <= 5 characters
  NavaidKind kind = NavaidKind::kVor;
  double bearing_rad = 0.0;  // from the aircraft, magnetic (as NdInputs::heading_rad) [rad]
  double distance_m = 0.0;   // ground distance from the aircraft [m]
};

struct NdInputs {
  double heading_rad = 0.0;                    // magnetic heading (heading up) [rad]
  double track_rad = 0.0;                      // magnetic ground track (the track line) [rad]
  std::optional<double> selected_heading_rad;  // MCP heading bug [rad]
  double selected_course_rad = 0.0;            // the course pointer (OBS), magnetic [rad]
  NavSignal course = NavSignal::kNotTuned;     // the VOR / localizer the HSI shows
  bool course_is_localizer = false;            // flag text "LOC" rather than "VOR"
  std::string course_ident;                    // the station (<= 5 characters)
  double course_deviation_dots = 0.0;          // + fly right [dots]
  ToFrom to_from = ToFrom::kOff;
  bool dme_valid = false;
  double dme_distance_m = 0.0;  // slant range [m] (drawn in NM)
  BearingPointer bearing1;
  BearingPointer bearing2;
  std::vector<Navaid> navaids;              // drawn when within range_nm
  double range_nm = 40.0;                   // compass-rose radius: 5..640 NM [NM]
  std::optional<double> ground_speed_mps;   // "GS" readout [m/s] (drawn in kt)
  std::optional<double> true_airspeed_mps;  // "TAS" readout [m/s]
};


void validate(const PfdInputs& in, std::string_view where);
void validate(const NdInputs& in, std::string_view where);

}  // namespace fedsim::displays
