// The autoland Monte Carlo: seeded, reproducible draws within their ranges, the percentiles
// against hand-computed order statistics, and a 3-landing smoke run through the writers (the
// full run, 100+ landings, is the program fedsim-autoland-mc, not a test).
#include "flight/autoland/monte_carlo/autoland_monte_carlo.hpp"
#include "common/util/build_paths.hpp"
#include "flight/model/afcs/ils_approach_source.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <sstream>
#include <stdexcept>

namespace fedsim::flight::autoland {
namespace {

constexpr double kKt = units::kKtToMps;
constexpr double kFt = units::kFtToM;

const nav::IlsApproach& ksfo_28r() {
  static const nav::IlsApproach ils =
      afcs::with_course_through_threshold(afcs::load_default_ils_approach("KSFO", "28R"));
  return ils;
}

std::vector<Scenario> draws(std::uint64_t seed, int n) {
  std::mt19937_64 rng(seed);
  std::vector<Scenario> out;
  for (int i = 0; i < n; ++i) out.push_back(draw_scenario(rng, ScenarioRanges{}, ksfo_28r(), i));
  return out;
}

TEST(AutolandMonteCarlo, DrawsAreSeededAndWithinTheirRanges) {
  const auto a = draws(7, 500), b = draws(7, 500), c = draws(8, 500);
  int turbulence[3] = {0, 0, 0};
  const ScenarioRanges r;
  for (std::size_t i = 0; i < a.size(); ++i) {
    EXPECT_EQ(a[i].wind_from_rad, b[i].wind_from_rad);
    EXPECT_EQ(a[i].turbulence_seed, b[i].turbulence_seed);
    EXPECT_NE(a[i].fuel_kg, c[i].fuel_kg);  // another seed, other draws
    EXPECT_LE(a[i].wind_speed_mps, r.max_wind_mps);
    EXPECT_GE(a[i].headwind_mps, -r.max_tailwind_mps);  // the tailwind limit holds
    EXPECT_NEAR(std::hypot(a[i].headwind_mps, a[i].crosswind_mps), a[i].wind_speed_mps, 1e-9);
    EXPECT_GE(a[i].fuel_kg, r.min_fuel_kg);
    EXPECT_LE(a[i].fuel_kg, r.max_fuel_kg);
    EXPECT_GE(a[i].start_before_threshold_m, r.min_start_nm * units::kNmToM);
    EXPECT_LE(std::abs(a[i].start_left_m), r.max_start_offset_m);
    const double path = ksfo_28r().threshold.elevation_m + ksfo_28r().threshold_crossing_height_m +
                        a[i].start_before_threshold_m * std::tan(ksfo_28r().glide_path_angle_rad);
    EXPECT_GE(path - a[i].start_altitude_m, r.min_below_glide_path_m - 1e-9);
    EXPECT_LE(path - a[i].start_altitude_m, r.max_below_glide_path_m + 1e-9);
    ++turbulence[static_cast<int>(a[i].turbulence)];
  }
  // 0.25 / 0.5 / 0.25 of 500: each within 4 standard deviations of its expectation.
  EXPECT_NEAR(turbulence[0], 125, 4 * std::sqrt(500 * 0.25 * 0.75));
  EXPECT_NEAR(turbulence[1], 250, 4 * std::sqrt(500 * 0.5 * 0.5));
  EXPECT_NEAR(turbulence[2], 125, 4 * std::sqrt(500 * 0.25 * 0.75));
}

TEST(AutolandMonteCarlo, PercentilesAreTheOrderStatisticsInterpolated) {
  std::vector<double> v;
  for (int i = 100; i >= 1; --i) v.push_back(i);  // 1..100, unsorted
  const Percentiles p = percentiles(v);
  EXPECT_EQ(p.min, 1.0);
  EXPECT_EQ(p.max, 100.0);
  EXPECT_DOUBLE_EQ(p.p50, 50.5);  // type 7: 1 + 99 q
  EXPECT_DOUBLE_EQ(p.p5, 5.95);
  EXPECT_DOUBLE_EQ(p.p95, 95.05);
  EXPECT_DOUBLE_EQ(p.p1, 1.99);
}

TEST(AutolandMonteCarlo, BadRangesAreNamed) {
  ScenarioRanges r;
  r.max_fuel_kg = -1.0;
  EXPECT_THROW(r.validate(), std::invalid_argument);
  r = ScenarioRanges{};
  r.min_below_glide_path_m = 2000.0;
  try {
    r.validate();
    FAIL();
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("below_glide_path"), std::string::npos) << e.what();
  }
}

TEST(AutolandMonteCarlo, SmokeRunOfThreeLandings) {
  const auto runway = RunwayCentreline::from_table(RunwayTable::load_default(), "KSFO", "28R");
  const AircraftPack pack = load_aircraft_pack(fedsim::util::data_dir() + "/aircraft/b737.yaml");
  std::vector<RunResult> results;
  for (const Scenario& s : draws(1, 3)) results.push_back(fly_scenario(s, pack, ksfo_28r(), runway));
  for (const RunResult& r : results) {
    const afcs::Touchdown& t = r.figures.touchdown;
    std::printf("run %d (%.1f kt from %.0f deg, %s turbulence, %.1f t): %.0f ft beyond, %+.1f ft, %.2f ft/s, "
                "bank %+.1f deg, stopped %.0f m beyond\n",
                r.scenario.run, r.scenario.wind_speed_mps / kKt, r.scenario.wind_from_rad / units::kDegToRad,
                std::string(to_string(r.scenario.turbulence)).c_str(), r.mass_kg / 1000.0,
                t.beyond_threshold_m / kFt, r.figures.touchdown_left_of_centreline_m / kFt, t.sink_rate_mps / kFt,
                t.roll_rad / units::kDegToRad, r.figures.stop_beyond_threshold_m);
    EXPECT_TRUE(r.figures.touched_down);
    EXPECT_TRUE(r.figures.stopped);
    EXPECT_TRUE(r.violations.empty()) << r.violations.front();
  }
  // The same scenario flies the same landing.
  const RunResult again = fly_scenario(results[1].scenario, pack, ksfo_28r(), runway);
  EXPECT_EQ(again.figures.touchdown.time_s, results[1].figures.touchdown.time_s);
  EXPECT_EQ(again.figures.touchdown.sink_rate_mps, results[1].figures.touchdown.sink_rate_mps);
  // The writers: a header and one row each; the percentile table names its limits.
  std::ostringstream csv, table, gp;
  write_touchdowns_csv(csv, results);
  const std::string rows = csv.str();
  EXPECT_EQ(std::count(rows.begin(), rows.end(), '\n'), 4);
  write_percentiles_markdown(table, results, afcs::LandingLimits{});
  EXPECT_NE(table.str().find("| sink rate | ft/s |"), std::string::npos);
  EXPECT_NE(table.str().find("< 6.0"), std::string::npos);
  write_scatter_gnuplot(gp, "t.csv", "t.png", afcs::LandingLimits{}, "smoke");
  EXPECT_NE(gp.str().find("set object 1 rect from 200,-27 to 2700,27"), std::string::npos) << gp.str();
}

}  // namespace
}  // namespace fedsim::flight::autoland
