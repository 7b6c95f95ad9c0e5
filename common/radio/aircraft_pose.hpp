// The aircraft state every radio receiver and the flight director read, SI: WGS-84 geodetic
// position, height above mean sea level, true heading and attitude (3-2-1 Euler angles of the body
// relative to local NED, docs/frames.md), true airspeed and rate of climb.
//
// Per-frame data: the receivers do not throw on a bad pose; they return a reading with status
// kInvalidInput (flagged) so one bad sample cannot stop the federate. The adapter should check the
// sample first with pose_problem() and count a fault when it is not empty.
#pragma once

#include <string_view>

namespace fedsim::radio {

struct AircraftPose {
  double lat_rad = 0.0;            // geodetic latitude [rad], [-pi/2, pi/2]
  double lon_rad = 0.0;            // longitude, east positive [rad], [-2 pi, 2 pi]
  double altitude_msl_m = 0.0;     // height of the receiving antennas above MSL [m], [-1000, 100000]
  double heading_true_rad = 0.0;   // psi, true heading [rad], any finite value (wrapped)
  double pitch_rad = 0.0;          // theta [rad], [-pi/2, pi/2]
  double roll_rad = 0.0;           // phi, + right wing down [rad], [-pi, pi]
  double true_airspeed_mps = 0.0;  // [m/s], [0, 1000]
  double climb_rate_mps = 0.0;     // rate of climb, + up [m/s], [-500, 500]
};

/// The first field of `pose` that is not finite or outside its stated range, as its name
/// ("lat_rad", ...); empty when the pose is fine.
std::string_view pose_problem(const AircraftPose& pose);

}  // namespace fedsim::radio
