#include "flight/model/afcs/approach_progress.hpp"

#include "common/units/units.hpp"

#include <cmath>
#include <cstdio>

namespace fedsim::flight::afcs {

std::string_view to_string(ApproachPhase phase) {
  switch (phase) {
    case ApproachPhase::kManual: return "manual";
    case ApproachPhase::kIntercept: return "intercept";
    case ApproachPhase::kLocalizer: return "localizer";
    case ApproachPhase::kGlideSlope: return "glide slope";
    case ApproachPhase::kFlare: return "flare";
    case ApproachPhase::kRollout: return "rollout";
    case ApproachPhase::kStopped: return "stopped";
    case ApproachPhase::kGoAround: return "go-around";
  }
  return "?";
}

ApproachPhase approach_phase(const ModeState& modes, const ApproachAircraft& aircraft) {
  // The ground first: after the autopilot disconnects at the stop the aircraft is still stopped.
  if (aircraft.on_ground && aircraft.ground_speed_mps < kStoppedSpeedMps) return ApproachPhase::kStopped;
  if (modes.lateral == LateralMode::kGoAround || modes.vertical == VerticalMode::kGoAround)
    return ApproachPhase::kGoAround;
  if (aircraft.on_ground) return ApproachPhase::kRollout;
  if (modes.vertical == VerticalMode::kFlare || modes.lateral == LateralMode::kAlign) return ApproachPhase::kFlare;
  if (!modes.autopilot_engaged && !modes.flight_director_on) return ApproachPhase::kManual;
  if (modes.vertical == VerticalMode::kGlideSlope) return ApproachPhase::kGlideSlope;
  if (modes.lateral == LateralMode::kLocalizer && !modes.vor) return ApproachPhase::kLocalizer;
  return ApproachPhase::kIntercept;
}

namespace {
// A column with no mode shows "-" (the FMA leaves it blank).
template <class Mode>
std::string column(Mode mode) {
  const std::string_view name = to_string(mode);
  return name.empty() ? "-" : std::string(name);
}

std::string fma(const ModeState& m) {
  std::string out = column(m.thrust) + " | " + column(m.lateral);
  if (m.lateral_armed.localizer) out += " +vor/loc";
  if (m.lateral_armed.rollout) out += " +rollout";
  out += " | " + column(m.vertical);
  if (m.vertical_armed.glide_slope) out += " +g/s";
  if (m.vertical_armed.flare) out += " +flare";
  if (m.vertical_armed.altitude_capture) out += " +alt acq";
  out += m.autopilot_engaged ? " | CMD" : (m.flight_director_on ? " | FD" : " | AP off");
  return out;
}
}  // namespace

std::string approach_progress_line(const ModeState& modes, const ApproachAircraft& aircraft,
                                   const RunwayCentreline* runway) {
  const ApproachPhase phase = approach_phase(modes, aircraft);
  char where[96] = "";
  if (runway) {
    const double beyond_m = runway->beyond_threshold_m(aircraft.lat_rad, aircraft.lon_rad);
    if (beyond_m < 0.0) {
      std::snprintf(where, sizeof where, " %.1f NM to the threshold,", -beyond_m / units::kNmToM);
    } else {
      std::snprintf(where, sizeof where, " %.0f m beyond the threshold,", beyond_m);
    }
  }
  char figures[96];
  if (aircraft.on_ground) {
    std::snprintf(figures, sizeof figures, " %.0f kt over the ground",
                  aircraft.ground_speed_mps / units::kKtToMps);
  } else {
    std::snprintf(figures, sizeof figures, " %.0f ft, %.0f KCAS", aircraft.height_agl_m / units::kFtToM,
                  aircraft.cas_mps / units::kKtToMps);
  }
  return std::string(to_string(phase)) + ":" + where + figures + " | " + fma(modes);
}

}  // namespace fedsim::flight::afcs
