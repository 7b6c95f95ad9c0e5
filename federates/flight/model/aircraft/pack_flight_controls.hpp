// Flight-control section of an aircraft pack: surface travel and actuator figures (SI).
#pragma once

#include <optional>
#include <vector>

#include "common/math/interpolation.hpp"

namespace fedsim::flight {

/// A surface driven by a normalised command in -1..1 (elevator, aileron, rudder). The command
/// maps piecewise-linearly to a demanded deflection (0 -> 0, +1 -> deflection_at_plus_one_rad,
/// -1 -> deflection_at_minus_one_rad, as JSBSim's zero-centred aerosurface_scale); a first-order
/// lag and a rate limit act on the demand, and the result is clipped to [min, max].
struct SurfaceActuatorSpec {
  double deflection_at_plus_one_rad = 0.0;
  double deflection_at_minus_one_rad = 0.0;
  double min_deflection_rad = 0.0;  // clip; defaults to the smaller travel end
  double max_deflection_rad = 0.0;  // clip; defaults to the larger travel end
  double time_constant_s = 0.0;     // 0: the surface follows the demand without lag
  double rate_limit_radps = 0.0;    // 0: no rate limit

  /// Demanded deflection for a command (clamped to -1..1 first), before lag and rate limit.
  double demanded_deflection_rad(double command) const {
    const double c = command > 1.0 ? 1.0 : (command < -1.0 ? -1.0 : command);
    return c >= 0.0 ? c * deflection_at_plus_one_rad : -c * deflection_at_minus_one_rad;
  }
};

/// A surface that moves between fixed positions at stated speeds (flaps, speedbrake, spoilers;
/// JSBSim's "kinematic" component). Positions are normalised 0..1; moving from position i-1 to i
/// takes transit_times_s[i-1] seconds (linear in between).
struct KinematicSurfaceSpec {
  std::vector<double> positions_norm;   // strictly increasing, first 0, last 1
  std::vector<double> transit_times_s;  // one fewer than positions, each >= 0
  double full_travel_rad = 0.0;         // deflection at position 1 (flaps; 0 if not stated)
};

/// The yaw damper (model/systems/yaw_damper.hpp): rudder command = K(Mach) x washout(r), r the
/// body yaw rate relative to the air mass. On at the start of a run unless engaged_at_start is
/// false (the instructor or the aircraft's switch can change it: AircraftModel::set_yaw_damper_engaged).
struct YawDamperSpec {
  Table1D gain_per_radps;                // normalised rudder per rad/s against Mach (< 0 damps)
  double washout_time_constant_s = 0.0;  // 0: no washout
  double authority = 1.0;                // |damper command| limit, (0, 1]
  bool engaged_at_start = true;
};

/// The wing leveller (model/systems/wing_leveller.hpp, the JSBSim C172 autopilot's "Roll wing
/// leveler"): aileron command = -(Kp phi + Ki integral(phi) + Kd dphi/dt), added to the pilot's
/// aileron and trim. Off at the start of a run unless engaged_at_start (the pilot's switch,
/// AircraftModel::set_wing_leveller_engaged, turns it on).
struct WingLevellerSpec {
  double bank_gain_per_rad = 0.0;
  double bank_integral_gain_per_rad_s = 0.0;
  double bank_rate_gain_per_radps = 0.0;
  bool airborne_only = true;
  bool engaged_at_start = false;
};

/// Pitch trim with a trim rate: AircraftControls::elevator_trim is the position the trim is
/// driven to; the trim moves there at rate_per_s (normalised trim travel, -1..1, per second).
/// Its position adds to the elevator command before the elevator's clip (JSBSim's
/// "Pitch Trim Sum", the way the source data of both packs model the trim). `kind` records
/// what moves: the 737's trimmable horizontal stabiliser or the C172's elevator trim tab.
enum class PitchTrimKind { kStabiliser, kTab };
struct PitchTrimSpec {
  PitchTrimKind kind = PitchTrimKind::kStabiliser;
  double rate_per_s = 0.0;  // > 0
};

/// All surfaces the pack defines; a missing surface is absent (the NASA sphere has none).
struct FlightControlsSpec {
  std::optional<SurfaceActuatorSpec> elevator;
  std::optional<SurfaceActuatorSpec> aileron;
  std::optional<SurfaceActuatorSpec> rudder;
  std::optional<KinematicSurfaceSpec> flaps;
  std::optional<KinematicSurfaceSpec> speedbrake;
  std::optional<KinematicSurfaceSpec> spoilers;
  std::optional<YawDamperSpec> yaw_damper;    // absent: no yaw damper
  std::optional<PitchTrimSpec> pitch_trim;    // absent: the trim follows its command at once
  std::optional<WingLevellerSpec> wing_leveller;  // absent: no wing leveller
};

}  // namespace fedsim::flight
