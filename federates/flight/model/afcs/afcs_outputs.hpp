// What the AFCS commands every frame and what it annunciates.
//
// Commands are in the flight model's normalised units (AircraftControls, DESIGN.md "Control
// conventions") and replace the pilot's commands for the channels flagged as engaged:
//   elevator, aileron, rudder    -1..1 (the autopilot's servos back-drive column, wheel, pedals);
//   throttle                      0..1, every engine (autothrottle);
//   pitch_trim_command            -1, 0, +1: the trim motor running nose down (+1, the elevator
//                                 sense), stopped, nose up (-1): the autopilot's auto-trim that
//                                 unloads the elevator servo; the aircraft's trim system moves at
//                                 its own trim rate (model/systems pitch trim);
//   steering, brakes, spoilers    rollout: nose-wheel steering -1..1 (+ nose right), autobrake
//                                 0..1 each side, ground spoilers 0..1 (auto speedbrake).
// The flight director's bars (attitude commands) are given whenever a mode is active.
#pragma once

#include "flight/model/afcs/afcs_modes.hpp"

#include <cstdint>

namespace fedsim::flight::afcs {

/// Alert flags (bit mask): what the master caution / autopilot warning lights show.
enum AfcsAlert : std::uint32_t {
  kAlertNone = 0,
  kAlertAutopilotDisconnect = 1u << 0,    // red AP light + wailer until the second press
  kAlertAutothrottleDisconnect = 1u << 1, // red A/T light
  kAlertLocalizerInvalid = 1u << 2,       // the localizer flagged while flown
  kAlertGlideSlopeInvalid = 1u << 3,      // the glide slope flagged while flown
  kAlertInputInvalid = 1u << 4,           // a non-finite or out-of-range input sample
  kAlertEngageRefused = 1u << 5,          // engagement conditions not met (on ground, attitude)
  kAlertAttitudeLimit = 1u << 6,          // bank or pitch beyond the autopilot's authority
  kAlertAutopilotFailed = 1u << 7,        // the autopilot failed (instructor): disengaged, refuses CMD
  kAlertAutothrottleFailed = 1u << 8,     // the autothrottle failed (instructor)
  kAlertVorInvalid = 1u << 9,             // the VOR flagged while flown (not the cone overhead)
};

/// The flight-mode annunciator.
struct Fma {
  ThrustMode thrust = ThrustMode::kNone;
  LateralMode lateral = LateralMode::kNone;
  LateralArmed lateral_armed;
  VerticalMode vertical = VerticalMode::kNone;
  VerticalArmed vertical_armed;
  bool autopilot_engaged = false;     // "CMD"
  bool flight_director_on = false;    // "FD"
  bool autothrottle_engaged = false;  // A/T armed or active
  std::uint32_t alerts = kAlertNone;  // AfcsAlert bits, latched until acknowledged
  bool vor = false;                   // VOR/LOC flies a VOR (not the localizer)
  bool vor_over_station = false;      // ... holding the course over the station
  friend bool operator==(const Fma&, const Fma&) = default;
};

struct AfcsOutputs {
  bool autopilot_engaged = false;     // elevator, aileron, rudder, trim below are to be applied
  double elevator = 0.0;              // -1..1, + nose down
  double aileron = 0.0;               // -1..1, + right wing down
  double rudder = 0.0;                // -1..1, + nose right
  int pitch_trim_command = 0;         // -1 nose up, 0 off, +1 nose down
  bool autothrottle_engaged = false;  // throttle below is to be applied
  double throttle = 0.0;              // 0..1 all engines
  bool rollout_engaged = false;       // steering, brakes, spoilers below are to be applied
  double steering = 0.0;              // -1..1, + nose right
  double brake_left = 0.0;            // 0..1
  double brake_right = 0.0;           // 0..1
  double spoilers = 0.0;              // 0..1 ground spoilers
  // Flight director (valid when a roll / pitch mode is active).
  bool flight_director_roll_valid = false;
  double flight_director_roll_rad = 0.0;   // bank command, + right wing down
  bool flight_director_pitch_valid = false;
  double flight_director_pitch_rad = 0.0;  // pitch command, + nose up
  Fma fma;
  // Guidance quantities for displays, recorders and tests.
  double flight_path_command_rad = 0.0;   // gamma_c of the active path mode (0 otherwise)
  double cross_track_left_m = 0.0;        // from the localizer, or the VOR VOR/LOC flies (0 when not valid)
  double glide_path_height_error_m = 0.0; // + below the path (0 when not valid)
};

}  // namespace fedsim::flight::afcs
