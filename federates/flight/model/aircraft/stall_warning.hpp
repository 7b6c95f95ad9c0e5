// The stall-warning angle of attack of a pack, for a stick shaker (fedsim-control-loading
// --aircraft): from the pack's own lift build-up, the angle of maximum lift CL_max at a flap
// setting, and the angle where the lift coefficient first reaches CL_max / k^2, the lift at a
// speed k times the stall speed in steady flight (L = W: CL ~ 1/V^2). 14 CFR 25.207(c) asks the
// warning to begin at least 5 kt or 5 % above the stall speed: k = 1.05 is that minimum.
//
// The sweep: alpha from 0 in 0.001 rad steps to the first local maximum of CL (the pre-stall
// branch: stall hysteresis off, out of ground effect, beta 0, no rates, Mach 0.2, gear down,
// surfaces neutral), at most to the pack's attached-flow envelope.
#pragma once

#include "flight/model/aircraft/aircraft_pack.hpp"

namespace fedsim::flight {

struct StallAngles {
  double flap_norm = 0.0;
  double alpha_cl_max_rad = 0.0;  ///< the angle of maximum lift
  double cl_max = 0.0;
  double alpha_warning_rad = 0.0; ///< where CL first reaches cl_max / k^2
};

/// Throws std::invalid_argument for flap_norm outside [0, 1], k < 1 or a pack whose lift never
/// rises with alpha (no stall to warn of).
StallAngles stall_angles(const AircraftPack& pack, double flap_norm, double speed_margin = 1.05);

}  // namespace fedsim::flight
