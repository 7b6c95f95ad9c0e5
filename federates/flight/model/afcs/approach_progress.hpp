// The progress of an ILS approach and landing as a person watching the run wants it: the phase
// of flight (from the AFCS's modes and the aircraft's state), the distance to go to the runway's
// threshold (then along the runway), the height, the speed and the FMA. The flight federate
// sends it with its periodic status; `fedsim run` prints it in its progress lines.
#pragma once

#include "flight/model/afcs/landing_figures.hpp"
#include "flight/model/afcs/mode_logic.hpp"

#include <string>
#include <string_view>

namespace fedsim::flight::afcs {

enum class ApproachPhase {
  kManual,      // autopilot and flight director off: nobody flies the approach for us
  kIntercept,   // before the localizer: heading or altitude modes, LOC armed or not yet
  kLocalizer,   // on the localizer, below or above the glide slope (G/S armed)
  kGlideSlope,  // on the localizer and the glide slope
  kFlare,       // flare (and align) near the ground
  kRollout,     // on the runway, moving
  kStopped,     // on the ground, stopped
  kGoAround,    // TOGA
};
std::string_view to_string(ApproachPhase phase);

/// What the progress line reads of the aircraft (SI).
struct ApproachAircraft {
  double lat_rad = 0.0, lon_rad = 0.0;
  double height_agl_m = 0.0;      // above the runway plane
  double cas_mps = 0.0;
  double ground_speed_mps = 0.0;
  bool on_ground = false;
};

/// Below this ground speed on the ground the aircraft counts as stopped [m/s] (about 1 kt).
inline constexpr double kStoppedSpeedMps = 0.5;

ApproachPhase approach_phase(const ModeState& modes, const ApproachAircraft& aircraft);

/// "glide slope: 3.2 NM to the threshold, 1020 ft, 145 kt | SPD | VOR/LOC | G/S" (armed modes in
/// lower case after a '+'); on the runway the distance is the one beyond the threshold, in
/// metres. Without a runway (nullptr) the distance is left out.
std::string approach_progress_line(const ModeState& modes, const ApproachAircraft& aircraft,
                                   const RunwayCentreline* runway);

}  // namespace fedsim::flight::afcs
