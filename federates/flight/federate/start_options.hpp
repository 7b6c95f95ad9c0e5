// How a flight run starts, from the command line: an initial-condition file, or a trim
// (--trim level|climb|turn|ground with its conditions), as fedsim-fly and fedsim-flight share.
#pragma once

#include "flight/model/aircraft/aircraft_model.hpp"
#include "flight/model/scenario/reposition.hpp"

#include <CLI/CLI.hpp>

#include <optional>
#include <string>

namespace fedsim::flight {

struct StartOptions {
  std::string ic_file;             // --ic
  std::string trim_kind;           // --trim level|climb|turn|ground
  double alt_ft = 4000.0;          // --alt-ft (MSL)
  double ktas = 0.0;               // --ktas (true airspeed, knots)
  double kcas = 0.0;               // --kcas (calibrated airspeed, knots)
  double heading_deg = 0.0;        // --heading (true)
  double lat_deg = 37.6;           // --lat
  double lon_deg = -122.4;         // --lon
  double gamma_deg = 0.0;          // --gamma-deg (climb)
  double bank_deg = 0.0;           // --bank-deg (turn)
  double flaps = 0.0;              // --flaps 0..1
  std::optional<double> throttle;  // --throttle 0..1: engines' throttle on a ground start
  std::optional<double> runway_elevation_m;  // --runway-elevation-m
  std::string airport, runway;     // --airport/--runway: start at that threshold (ground trim)
  // --approach-nm with --airport/--runway: start in level flight before that runway instead.
  std::optional<double> approach_nm;   // --approach-nm: before the threshold along the centreline
  double approach_offset_nm = 0.0;     // --approach-offset-nm: left (+) / right (-) of it
  double intercept_deg = 0.0;          // --intercept-deg: heading towards the centreline
  bool gear_down = false;              // --gear-down: the gear down in a flight trim
};

/// Adds the options above to `app`.
void add_start_options(CLI::App& app, StartOptions& options);

/// What a run starts from: the model is left in the start state with the start controls set.
struct StartState {
  AircraftInitialConditions initial;
  AircraftControls controls;
  std::optional<TrimResult> trim;  // when trimmed
};

/// Puts the model in the start state (reads the IC file, or trims). Throws util::ConfigError or
/// std::invalid_argument for bad input; a trim that does not converge is returned with
/// trim->converged false (the caller decides).
StartState establish_start(const StartOptions& options, AircraftModel& model);

/// The trim solution as one JSON object (alpha, pitch, surfaces, throttle, residuals...).
std::string trim_json(const TrimResult& trim);

}  // namespace fedsim::flight
