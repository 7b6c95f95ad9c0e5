// The flight director's commands as the displays show them: bars on the PFD, the guidance cue
// on the HUD. From the autopilot's fd_* fields (or the navigation federate's own FD computer):
// absolute attitudes, not errors.
#pragma once

#include <string_view>

namespace fedsim::symbology {

struct FlightDirector {
  bool on = false;                 // FD switch on: bars (valid) or the FD flag (not valid)
  bool pitch_valid = false;        // a pitch mode is active
  bool roll_valid = false;         // a roll mode is active
  double pitch_command_rad = 0.0;  // commanded pitch attitude, + nose up [rad]
  double roll_command_rad = 0.0;   // commanded bank, + right wing down [rad]
};

/// Throws std::invalid_argument "<where>: field 'flight_director.pitch_command_rad': ..." for a
/// command that is not finite or beyond +-90 deg pitch, +-180 deg bank.
void validate(const FlightDirector& fd, std::string_view where);

}  // namespace fedsim::symbology
