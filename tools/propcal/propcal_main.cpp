// fedsim-propcal: identifies a fixed-pitch propeller's CT and CP factors (JSBSim's <ct_factor>,
// <cp_factor>; constant, or faded out over a stated advance-ratio band) from a published static
// full-throttle rpm and take-off ground roll, flying both through the flight model
// (identify_propeller_factors; procedure and the C172's figures in data/aircraft/README.md,
// "Calibration"). Prints the factors and the runs they give; the factors go into the pack's
// calibration overlay (data/aircraft/<pack>.calibration.yaml).
#include <CLI/CLI.hpp>
#include "common/util/build_paths.hpp"

#include <cstdio>
#include <exception>
#include <stdexcept>
#include <string>

#include "common/util/cli_checks.hpp"
#include "common/units/units.hpp"
#include "flight/model/aircraft/aircraft_pack.hpp"
#include "flight/model/scenario/propeller_calibration.hpp"
#include "flight/model/systems/propeller.hpp"

namespace {

using namespace fedsim;
using namespace fedsim::flight;

std::string pack_path(const std::string& aircraft) {
  if (aircraft.find('/') != std::string::npos || aircraft.ends_with(".yaml")) return aircraft;
  return fedsim::util::data_dir() + "/aircraft/" + aircraft + ".yaml";
}

void print_runs(const char* what, const StaticRunUp& s, const TakeoffRoll& r) {
  std::printf("%s: static %.1f rpm, %.1f hp, %.0f N, MAP %.2f inHg; ground roll %.1f ft "
              "(%.1f m), lift-off %.1f KCAS, J %.3f, after %.1f s\n",
              what, s.rpm, s.power_w / units::kHpToW, s.thrust_n,
              s.manifold_pressure_pa / units::kInHgToPa, r.ground_roll_m * units::kMToFt,
              r.ground_roll_m, r.liftoff_cas_mps / units::kKtToMps, r.liftoff_advance_ratio, r.time_s);
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"Identify a fixed-pitch propeller's CT and CP factors from a published static "
               "rpm and take-off ground roll (sea level, ISA, no wind); with --fade-start-j and "
               "--fade-end-j the factors apply in full below the first advance ratio and fade "
               "linearly to none at the second."};
  std::string aircraft;
  double static_rpm = 0.0;
  double ground_roll_ft = 0.0;
  double flaps_deg = 0.0;
  double rotate_kcas = 0.0;
  double fade_start_j = 0.0;
  double fade_end_j = 0.0;
  PropellerCalibrationTargets targets;
  app.add_option("--aircraft", aircraft, "aircraft pack: a YAML file, or a name in data/aircraft")
      ->required();
  app.add_option("--static-rpm", static_rpm, "published static full-throttle rpm, sea level")
      ->required()
      ->check(fedsim::util::kFinitePositive);
  app.add_option("--ground-roll-ft", ground_roll_ft, "published take-off ground roll (ft)")
      ->required()
      ->check(fedsim::util::kFinitePositive);
  app.add_option("--flaps-deg", flaps_deg, "take-off flap setting (deg)")->check(fedsim::util::FiniteRange(0.0, 90.0));
  app.add_option("--rotate-kcas", rotate_kcas, "rotation speed (KCAS)")
      ->required()
      ->check(fedsim::util::kFinitePositive);
  CLI::Option* fade_start =
      app.add_option("--fade-start-j", fade_start_j,
                     "advance ratio up to which the factors apply in full")
          ->check(fedsim::util::FiniteRange(0.0, Propeller::kMaxFadeAdvanceRatio));
  CLI::Option* fade_end =
      app.add_option("--fade-end-j", fade_end_j,
                     "advance ratio from which the factors are 1 (linear fade in between)")
          ->check(fedsim::util::FiniteRange(0.0, Propeller::kMaxFadeAdvanceRatio));
  fade_start->needs(fade_end);
  fade_end->needs(fade_start);
  app.add_option("--rotation-elevator", targets.technique.rotation_elevator,
                 "elevator command held from rotation (-1..1, negative = stick back)")
      ->capture_default_str();
  app.add_option("--rate", targets.technique.frame_rate_hz, "frames per second")
      ->capture_default_str();
  app.add_option("--factor-low", targets.factor_low, "lower end of the factors' search bracket")
      ->capture_default_str();
  app.add_option("--factor-high", targets.factor_high, "upper end of the factors' search bracket")
      ->capture_default_str();
  CLI11_PARSE(app, argc, argv);

  try {
    const AircraftPack pack = load_aircraft_pack(pack_path(aircraft));
    if (flaps_deg > 0.0) {
      if (!pack.flight_controls.flaps || !(pack.flight_controls.flaps->full_travel_rad > 0.0)) {
        throw std::invalid_argument("--flaps-deg: the pack states no flap travel");
      }
      targets.technique.flaps_norm =
          flaps_deg * units::kDegToRad / pack.flight_controls.flaps->full_travel_rad;
    }
    targets.static_rpm = static_rpm;
    targets.ground_roll_m = ground_roll_ft * units::kFtToM;
    targets.technique.rotate_cas_mps = rotate_kcas * units::kKtToMps;
    if (*fade_start) targets.factor_fade = PropellerSpec::FactorFade{fade_start_j, fade_end_j};

    AircraftPack as_is = pack;
    print_runs("pack as is", static_full_throttle(as_is), fly_takeoff_ground_roll(as_is, targets.technique));
    AircraftPack unfactored = pack;
    set_propeller_factors(unfactored, 1.0, 1.0);
    print_runs("factors 1.0", static_full_throttle(unfactored),
               fly_takeoff_ground_roll(unfactored, targets.technique));

    const PropellerCalibration cal = identify_propeller_factors(pack, targets);
    print_runs("identified", cal.static_run, cal.roll);
    std::printf("power_coefficient_factor: %.4f\nthrust_coefficient_factor: %.4f\n",
                cal.power_coefficient_factor, cal.thrust_coefficient_factor);
    if (targets.factor_fade) {
      std::printf("factor_fade_start_advance_ratio: %g\nfactor_fade_end_advance_ratio: %g\n",
                  targets.factor_fade->start_advance_ratio, targets.factor_fade->end_advance_ratio);
    } else {
      std::printf("(constant factors: no fade band)\n");
    }
    return 0;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "fedsim-propcal: %s\n", e.what());
    return 1;
  }
}
