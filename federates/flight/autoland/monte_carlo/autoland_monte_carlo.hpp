// A Monte Carlo of automatic landings: seeded draws of wind, turbulence, weight and start point,
// each flown by ClosedLoopFlight (the 737 pack, the AFCS, the ILS receivers) from a localizer
// intercept to a stop, judged against the AFCS issue's limits (landing_figures.hpp), with the
// touchdown table, the percentiles and a gnuplot scatter script. Pure (std, the flight model):
// the program (main.cpp) renders the plot.
//
// Draws (one std::mt19937_64 stream from the seed; run i's draws follow run i-1's):
//   wind           speed U(0, max_wind), from U(0, 360 deg), redrawn while the tailwind
//                  component exceeds max_tailwind (the 737's autoland tailwind limit: 10 kt);
//   turbulence     none / light / moderate with probabilities 0.25 / 0.5 / 0.25 (MIL-F-8785C
//                  Dryden, the flight model's), its own seed drawn;
//   weight         fuel U(2, 14) t: 39.6 to 51.7 t (the 737-300's maximum landing weight,
//                  51.7 t) with the pack's 37.6 t empty; the wing tanks fill first;
//   approach speed 145 KCAS x sqrt(mass / 48.5 t) (Vref goes with the square root of weight);
//   start          U(9, 11) NM before the threshold, U(-2, 2) km off the course converging at
//                  30 deg, U(600, 1200) ft below the glide path there (ATC's vectors join the
//                  localizer below the glide slope: the G/S is captured from below after the LOC),
//                  ALT HOLD, APP armed.
#pragma once

#include "common/airports/runway_centreline.hpp"
#include "common/airports/runway_table.hpp"
#include "common/navdb/nav_records.hpp"
#include "flight/model/afcs/closed_loop_flight.hpp"
#include "flight/model/afcs/landing_figures.hpp"
#include "flight/model/aircraft/aircraft_pack.hpp"
#include "flight/model/weather/turbulence.hpp"

#include <cstdint>
#include <memory>
#include <ostream>
#include <random>
#include <string>
#include <vector>

namespace fedsim::flight::autoland {

struct ScenarioRanges {
  double max_wind_mps = 15.0 * units::kKtToMps;
  double max_tailwind_mps = 10.0 * units::kKtToMps;
  double min_fuel_kg = 2000.0, max_fuel_kg = 14000.0;
  double reference_mass_kg = 48534.0;  // the approach speed's design mass (b737.yaml as shipped)
  double reference_cas_mps = 145.0 * units::kKtToMps;
  double min_start_nm = 9.0, max_start_nm = 11.0;
  double max_start_offset_m = 2000.0;
  double min_below_glide_path_m = 600.0 * units::kFtToM, max_below_glide_path_m = 1200.0 * units::kFtToM;
  /// Throws std::invalid_argument naming the first bad field.
  void validate() const;
};

struct Scenario {
  int run = 0;
  double wind_speed_mps = 0.0;
  double wind_from_rad = 0.0;    // true
  double headwind_mps = 0.0;     // along the course (+ head)
  double crosswind_mps = 0.0;    // + from the right
  Turbulence::Severity turbulence = Turbulence::Severity::kNone;
  std::uint64_t turbulence_seed = 0;
  double fuel_kg = 0.0;
  double approach_cas_mps = 0.0;
  double start_before_threshold_m = 0.0;
  double start_left_m = 0.0;
  double start_altitude_m = 0.0;
};

/// The next scenario from the stream (the approach gives the course and the glide path).
Scenario draw_scenario(std::mt19937_64& rng, const ScenarioRanges& ranges, const nav::IlsApproach& approach, int run);

struct RunResult {
  Scenario scenario;
  double mass_kg = 0.0;
  afcs::LandingFigures figures;
  std::vector<std::string> violations;  // empty: within every limit
  double flown_s = 0.0;
};

/// Flies one scenario from its start to a stop, at most max_time_s. With `flight` given, the
/// flight is kept there with its history (for a look at one landing), else nothing is recorded.
RunResult fly_scenario(const Scenario& scenario, const AircraftPack& pack, const nav::IlsApproach& approach,
                       const RunwayCentreline& runway, double max_time_s = 900.0,
                       std::unique_ptr<afcs::ClosedLoopFlight>* flight = nullptr);

/// min, 1st, 5th, 50th, 95th, 99th percentile, max (linear interpolation between order
/// statistics, Hyndman & Fan type 7).
struct Percentiles {
  double min = 0, p1 = 0, p5 = 0, p50 = 0, p95 = 0, p99 = 0, max = 0;
};
Percentiles percentiles(std::vector<double> values);

/// The touchdown table: one row per run (scenario, figures, violations).
void write_touchdowns_csv(std::ostream& out, const std::vector<RunResult>& results);
/// The percentiles of each touchdown figure, with the limit it is judged against, as CSV.
void write_percentiles_csv(std::ostream& out, const std::vector<RunResult>& results, const afcs::LandingLimits& limits);
/// The same as a Markdown table (for the docs and the console).
void write_percentiles_markdown(std::ostream& out, const std::vector<RunResult>& results,
                                const afcs::LandingLimits& limits);
/// A gnuplot script drawing the touchdown scatter (position on the runway, sink rate against
/// bank) with the limit boxes into `png_path`, reading `touchdowns_csv_path`.
void write_scatter_gnuplot(std::ostream& out, const std::string& touchdowns_csv_path, const std::string& png_path,
                           const afcs::LandingLimits& limits, const std::string& title);

std::string_view to_string(Turbulence::Severity severity);

}  // namespace fedsim::flight::autoland
