// Identification of a fixed-pitch propeller's CT and CP factors (JSBSim's <ct_factor>,
// <cp_factor>, constant or faded out over an advance-ratio band) from two published figures:
// the static full-throttle rpm and the take-off ground roll, both flown through AircraftModel.
#pragma once

#include <cstddef>
#include <optional>

#include "flight/model/aircraft/aircraft_model.hpp"
#include "flight/model/scenario/reposition.hpp"

namespace fedsim::flight {

/// The aircraft held on the brakes at the threshold of a sea-level runway (ISA, no wind),
/// engines at full throttle and full rich, settled (reposition_to_runway).
struct StaticRunUp {
  bool converged = false;  ///< the ground trim converged
  double rpm = 0.0;        ///< engine 0
  double power_w = 0.0;
  double thrust_n = 0.0;
  double manifold_pressure_pa = 0.0;
};

/// How the take-off is flown: flaps set and full power on the brakes, brakes released, the
/// elevator at its ground-trim position until the rotation speed, then held at
/// `rotation_elevator` until the wheels leave the ground.
struct TakeoffTechnique {
  double flaps_norm = 0.0;            ///< flap lever 0..1
  double rotate_cas_mps = 0.0;        ///< calibrated airspeed at which rotation starts (> 0)
  double rotation_elevator = -0.35;   ///< elevator command from rotation on (-1..0: stick back)
  double frame_rate_hz = 100.0;       ///< AircraftModel frames per second
  double time_limit_s = 90.0;         ///< give up (no lift-off) after this

  /// Throws std::invalid_argument naming the bad field.
  void validate() const;
};

struct TakeoffRoll {
  bool lifted_off = false;
  double ground_roll_m = 0.0;     ///< brake release to the last wheel leaving the ground
  double liftoff_cas_mps = 0.0;
  /// Engine 0's propeller advance ratio at lift-off, true airspeed / (n D): the largest of the
  /// roll (the thrust axis is within a few degrees of the path on the ground).
  double liftoff_advance_ratio = 0.0;
  double time_s = 0.0;            ///< brake release to lift-off
};

/// The model's options for both runs (RK4: the federate's integrator, stable on the gear).
AircraftModel::Options calibration_model_options();

/// Static run-up of `pack` (sea level, ISA, at rest, full throttle).
StaticRunUp static_full_throttle(const AircraftPack& pack);

/// Flies a take-off of `pack` from a sea-level runway (ISA, no wind, level, dry: the gear's
/// friction figures) with `technique`; the distance is measured along the ground from the
/// point of brake release.
TakeoffRoll fly_takeoff_ground_roll(const AircraftPack& pack, const TakeoffTechnique& technique);

/// Every piston engine's propeller gets these factors (its fade band, if any, stays).
void set_propeller_factors(AircraftPack& pack, double thrust_coefficient_factor,
                           double power_coefficient_factor);

/// Every piston engine's propeller gets this fade band (none: constant factors).
void set_propeller_factor_fade(AircraftPack& pack,
                               const std::optional<PropellerSpec::FactorFade>& fade);

struct PropellerCalibrationTargets {
  double static_rpm = 0.0;         ///< published static full-throttle rpm (sea level)
  double ground_roll_m = 0.0;      ///< published take-off ground roll (sea level, ISA)
  TakeoffTechnique technique;      ///< how the published ground roll was flown
  /// The advance-ratio band over which the identified factors fade out (a stated modelling
  /// choice, not identified: data/aircraft/README.md, "Calibration"); none: constant factors.
  /// Both figures should lie where the factors apply in full: the static rpm at J = 0 always
  /// does, the ground roll does when the lift-off advance ratio is at most the band's start.
  std::optional<PropellerSpec::FactorFade> factor_fade;
  /// Search bracket of both factors (within Propeller's accepted range).
  double factor_low = 0.5;
  double factor_high = 2.0;
  /// Bisection stops when the bracket is narrower than this.
  double factor_tolerance = 1e-5;

  /// Throws std::invalid_argument naming the bad field.
  void validate() const;
};

struct PropellerCalibration {
  double power_coefficient_factor = 1.0;
  double thrust_coefficient_factor = 1.0;
  StaticRunUp static_run;  ///< with both factors
  TakeoffRoll roll;        ///< with both factors
};

/// The procedure (data/aircraft/README.md, "Calibration"), with the propeller's fade band set
/// to `factor_fade` throughout:
///  1. bisection on the CP factor (CT factor 1) until the static full-throttle rpm is
///     `static_rpm`: a fixed-pitch propeller at rest (J = 0, where a factor applies in full)
///     absorbs CP rho n^3 D^5, so the rpm at which it takes the engine's power falls as the CP
///     factor rises; CT plays no part at rest;
///  2. with that CP factor, bisection on the CT factor until the flown ground roll is
///     `ground_roll_m`: the thrust at every speed of the roll scales with it (in full below the
///     band, less within it), the roll falls as it rises.
/// Throws std::invalid_argument if the pack has no piston engine, or if a target is not
/// reached anywhere in the bracket (the message gives what the bracket's ends reach), or if a
/// ground trim fails (a take-off without lift-off counts as an endless roll).
PropellerCalibration identify_propeller_factors(AircraftPack pack,
                                                const PropellerCalibrationTargets& targets);

}  // namespace fedsim::flight
