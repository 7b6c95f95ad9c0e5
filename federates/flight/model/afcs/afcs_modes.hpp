// The modes of the automatic flight control system (AFCS): what the flight-mode annunciator
// (FMA) of a 737-class primary flight display shows in its three columns (thrust, roll, pitch)
// and the engagement status. Names as the FMA abbreviations in comments.
#pragma once

#include <cstdint>
#include <string_view>

namespace fedsim::flight::afcs {

/// Roll (lateral) modes. Active: at most one; armed: see LateralArmed.
enum class LateralMode : std::uint8_t {
  kNone,           // no roll mode (autopilot and flight director off)
  kRollAttitude,   // "CWS R": holds the bank at engagement (or the pilot's wheel input)
  kWingLevel,      // "WLV": wings level, heading free
  kHeadingHold,    // "HDG HOLD": holds the heading captured when the wings came level
  kHeadingSelect,  // "HDG SEL": turns to and holds the MCP heading
  kLocalizer,      // "VOR/LOC": captured and tracking the localizer (or VOR) course
  kAlign,          // "ALIGN": below the align height in an autoland: decrab with the rudder
  kRollout,        // "ROLLOUT": on the runway, on the localizer with nose wheel and rudder
  kGoAround,       // "TOGA": holds the ground track at the go-around
};

/// Pitch (vertical) modes.
enum class VerticalMode : std::uint8_t {
  kNone,
  kPitchAttitude,    // "CWS P": holds the pitch attitude (or the pilot's column input)
  kAltitudeHold,     // "ALT HOLD"
  kAltitudeCapture,  // "ALT ACQ": asymptotic capture of the MCP altitude
  kVerticalSpeed,    // "V/S"
  kLevelChange,      // "MCP SPD" (level change): speed on the elevator, thrust fixed
  kGlideSlope,       // "G/S": captured and tracking the glide slope
  kFlare,            // "FLARE": exponential flare on the radio height
  kRollout,          // "ROLLOUT": derotation and nose-wheel hold on the runway
  kGoAround,         // "TOGA": go-around pitch (speed on the elevator, climb guaranteed)
};

/// Thrust modes (autothrottle).
enum class ThrustMode : std::uint8_t {
  kNone,      // autothrottle off
  kArm,       // "ARM": engaged, not moving the levers (pilot sets thrust)
  kSpeed,     // "MCP SPD": throttle holds the selected calibrated airspeed
  kClimb,     // "N1": climb thrust (level change up, the levers at the climb limit)
  kIdle,      // "RETARD"/"THR HLD" in a level-change descent: levers to idle, then held
  kRetard,    // "RETARD" in the flare: levers to idle at the retard rate
  kGoAround,  // "GA": thrust for the go-around climb rate
};

/// Modes that wait for their capture condition (shown small on the FMA's second line).
struct LateralArmed {
  bool localizer = false;  // "VOR/LOC" armed
  bool rollout = false;    // "ROLLOUT" armed (autoland below the flare-arm height)
  friend bool operator==(const LateralArmed&, const LateralArmed&) = default;
};
struct VerticalArmed {
  bool altitude_capture = false;  // "ALT ACQ" armed (the MCP altitude lies ahead)
  bool glide_slope = false;       // "G/S" armed
  bool flare = false;             // "FLARE" armed (G/S captured below the flare-arm height)
  friend bool operator==(const VerticalArmed&, const VerticalArmed&) = default;
};

std::string_view to_string(LateralMode mode);
std::string_view to_string(VerticalMode mode);
std::string_view to_string(ThrustMode mode);

/// True for the vertical modes that fly a flight-path angle through the path loop.
bool is_path_mode(VerticalMode mode);

}  // namespace fedsim::flight::afcs
