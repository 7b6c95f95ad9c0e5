// fedsim-autoland-mc: a Monte Carlo of seeded automatic landings of the 737 pack on an ILS runway
// (default KSFO 28R), flown in-process by the AFCS (no DDS). Writes, into --out:
//   touchdowns.csv   one row per landing (scenario and touchdown figures, limit violations);
//   percentiles.csv  min, 1, 5, 50, 95, 99 %, max of each figure with its limit;
//   percentiles.md   the same as a Markdown table (also printed);
//   touchdowns.gp    the gnuplot script, and touchdowns.png (rendered when gnuplot is installed);
// and prints the worst case of each figure. Exit status 0 when every landing is within the
// limits, 2 when some are not (the files are written either way), 1 on bad options.
#include "flight/autoland/monte_carlo/autoland_monte_carlo.hpp"
#include "common/util/build_paths.hpp"
#include "flight/model/afcs/ils_approach_source.hpp"

#include <CLI/CLI.hpp>

#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iostream>

namespace {

using namespace fedsim;
using namespace fedsim::flight;

struct Options {
  int runs = 100;
  std::uint64_t seed = 1;
  std::string out = "autoland-mc";
  std::string airport = "KSFO";
  std::string runway = "28R";
  bool quiet = false;
};

void print_worst(const std::vector<autoland::RunResult>& results) {
  const autoland::RunResult* worst_sink = nullptr;
  const autoland::RunResult* worst_offset = nullptr;
  const autoland::RunResult* longest = nullptr;
  for (const auto& r : results) {
    if (!r.figures.touched_down) continue;
    if (!worst_sink || r.figures.touchdown.sink_rate_mps > worst_sink->figures.touchdown.sink_rate_mps) worst_sink = &r;
    if (!worst_offset || std::abs(r.figures.touchdown_left_of_centreline_m) >
                             std::abs(worst_offset->figures.touchdown_left_of_centreline_m)) {
      worst_offset = &r;
    }
    if (!longest || r.figures.touchdown.beyond_threshold_m > longest->figures.touchdown.beyond_threshold_m) longest = &r;
  }
  auto describe = [](const char* what, const autoland::RunResult* r) {
    if (r == nullptr) return;
    const auto& s = r->scenario;
    std::printf("worst %s: run %d (wind %.1f kt from %.0f deg: %+.1f kt head, %+.1f kt cross; %s turbulence; %.1f t): "
                "%.0f ft beyond, %+.1f ft off the centreline, %.2f ft/s, bank %+.1f deg\n",
                what, s.run, s.wind_speed_mps / units::kKtToMps, s.wind_from_rad * units::kRadToDeg,
                s.headwind_mps / units::kKtToMps, s.crosswind_mps / units::kKtToMps,
                std::string(autoland::to_string(s.turbulence)).c_str(), r->mass_kg / 1000.0,
                r->figures.touchdown.beyond_threshold_m / units::kFtToM,
                r->figures.touchdown_left_of_centreline_m / units::kFtToM,
                r->figures.touchdown.sink_rate_mps / units::kFtToM, r->figures.touchdown.roll_rad * units::kRadToDeg);
  };
  describe("sink rate", worst_sink);
  describe("centreline offset", worst_offset);
  describe("touchdown distance", longest);
}

int run(const Options& o) {
  namespace fs = std::filesystem;
  fs::create_directories(o.out);
  const nav::IlsApproach approach =
      afcs::with_course_through_threshold(afcs::load_default_ils_approach(o.airport, o.runway));
  const RunwayCentreline runway =
      RunwayCentreline::from_table(RunwayTable::load_default(), o.airport, o.runway);
  const AircraftPack pack = load_aircraft_pack(fedsim::util::data_dir() + "/aircraft/b737.yaml");
  autoland::ScenarioRanges ranges;
  ranges.validate();
  std::mt19937_64 rng(o.seed);
  std::vector<autoland::RunResult> results;
  int failed = 0;
  for (int i = 0; i < o.runs; ++i) {
    const autoland::Scenario s = autoland::draw_scenario(rng, ranges, approach, i);
    results.push_back(autoland::fly_scenario(s, pack, approach, runway));
    const autoland::RunResult& r = results.back();
    if (!r.violations.empty()) ++failed;
    if (!o.quiet) {
      std::fprintf(stderr, "fedsim-autoland-mc: run %3d: %5.0f ft, %+5.1f ft, %4.2f ft/s, %+4.1f deg%s%s\n", i,
                   r.figures.touchdown.beyond_threshold_m / units::kFtToM,
                   r.figures.touchdown_left_of_centreline_m / units::kFtToM,
                   r.figures.touchdown.sink_rate_mps / units::kFtToM, r.figures.touchdown.roll_rad * units::kRadToDeg,
                   r.violations.empty() ? "" : "  OUTSIDE: ", r.violations.empty() ? "" : r.violations.front().c_str());
    }
  }
  const afcs::LandingLimits limits;
  const std::string csv = (fs::path(o.out) / "touchdowns.csv").string();
  { std::ofstream f(csv); autoland::write_touchdowns_csv(f, results); }
  { std::ofstream f(fs::path(o.out) / "percentiles.csv"); autoland::write_percentiles_csv(f, results, limits); }
  { std::ofstream f(fs::path(o.out) / "percentiles.md"); autoland::write_percentiles_markdown(f, results, limits); }
  const std::string gp = (fs::path(o.out) / "touchdowns.gp").string();
  const std::string png = (fs::path(o.out) / "touchdowns.png").string();
  {
    std::ofstream f(gp);
    char title[200];
    std::snprintf(title, sizeof title, "737 autoland, %s %s: %d seeded landings (seed %llu), %d outside the limits",
                  o.airport.c_str(), o.runway.c_str(), o.runs, static_cast<unsigned long long>(o.seed), failed);
    autoland::write_scatter_gnuplot(f, csv, png, limits, title);
  }
  const bool have_gnuplot = std::system("command -v gnuplot > /dev/null 2>&1") == 0;
  if (have_gnuplot) {
    if (std::system(("gnuplot '" + gp + "'").c_str()) != 0) std::fprintf(stderr, "fedsim-autoland-mc: gnuplot failed on %s\n", gp.c_str());
  } else {
    std::fprintf(stderr, "fedsim-autoland-mc: gnuplot not found: %s not rendered\n", png.c_str());
  }
  autoland::write_percentiles_markdown(std::cout, results, limits);
  print_worst(results);
  std::printf("%d of %d landings within every limit -> %s\n", o.runs - failed, o.runs, o.out.c_str());
  return failed == 0 ? 0 : 2;
}

}  // namespace

int main(int argc, char** argv) {
  Options o;
  CLI::App app{"fedsim-autoland-mc: a Monte Carlo of seeded 737 autolands (touchdown table, percentiles, scatter)"};
  app.add_option("--runs", o.runs, "landings to fly")->check(CLI::Range(1, 100000));
  app.add_option("--seed", o.seed, "seed of the scenario draws (std::mt19937_64)");
  app.add_option("--out", o.out, "output folder");
  app.add_option("--airport", o.airport, "ICAO ident of the ILS airport");
  app.add_option("--runway", o.runway, "ILS runway designator");
  app.add_flag("--quiet", o.quiet, "no per-landing lines");
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    return app.exit(e);
  }
  try {
    return run(o);
  } catch (const std::exception& e) {
    std::cerr << "fedsim-autoland-mc: " << e.what() << "\n";
    return 1;
  }
}
