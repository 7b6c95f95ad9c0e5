// fedsim-bench-navdb: query times of the navigation database (common/navdb) on the shipped
// OurAirports data.
//
// Measures, each over many seeded random queries, the median and 99th percentile of:
//   open      NavDatabase::open (schema checks, statements prepared)
//   within    every station within 50 NM of points in a dense region (Frankfurt, 50.04 N
//             8.56 E, +-1 deg latitude, +-1.5 deg longitude: ~23 stations per query)
//   nearest   nearest_on_frequency from points anywhere on earth, on frequencies in use
//   find      find(ident) for idents in the database
// Monotonic clock per query. The last line is one JSON object with every figure.
// Target: nearest tuned station well under 1 ms.
#include "common/navdb/nav_database.hpp"
#include "common/util/cli_checks.hpp"
#include "common/units/units.hpp"

#include <CLI/CLI.hpp>
#include "nav/model/avionics/avionics_suite.hpp"
#include "nav/model/avionics/database_station_source.hpp"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <iostream>
#include <random>
#include <set>
#include <string>
#include <vector>

namespace {

using fedsim::nav::NavDatabase;
using fedsim::units::kDegToRad;
using Clock = std::chrono::steady_clock;

struct Stats {
  double median_us = 0.0;
  double p99_us = 0.0;
  double max_us = 0.0;
  std::size_t count = 0;
};

Stats stats_of(std::vector<double> us) {
  std::sort(us.begin(), us.end());
  Stats s;
  s.count = us.size();
  s.median_us = us[us.size() / 2];
  s.p99_us = us[std::min(us.size() - 1, static_cast<std::size_t>(std::ceil(0.99 * us.size())) - 1)];
  s.max_us = us.back();
  return s;
}

template <typename Query>
Stats time_queries(int n, Query query) {
  std::vector<double> us;
  us.reserve(static_cast<std::size_t>(n));
  for (int i = 0; i < n; ++i) {
    const auto start = Clock::now();
    query(i);
    us.push_back(std::chrono::duration<double, std::micro>(Clock::now() - start).count());
  }
  return stats_of(std::move(us));
}

void print(const char* name, const Stats& s, const std::string& note) {
  std::printf("%-8s median %9.1f us   p99 %9.1f us   max %9.1f us   (%zu queries%s)\n", name,
              s.median_us, s.p99_us, s.max_us, s.count, note.c_str());
}

nlohmann::json to_json(const Stats& s) {
  return {{"median_us", s.median_us}, {"p99_us", s.p99_us}, {"max_us", s.max_us},
          {"queries", s.count}};
}

}  // namespace

/// Per-frame cost of the navigation federate's executive (every receiver, GPS, INS, flight
/// director) flying 50 m/s eastbound through the Frankfurt area at 3000 ft with NAV1, NAV2 and
/// the ADF tuned to the stations nearest the start; `gps`/`ins` off measures their share.
Stats time_suite_steps(const NavDatabase& db, int frames, bool gps, bool ins, std::string& tuned) {
  using namespace fedsim::nav;
  DatabaseStationSource stations(db);
  AvionicsConfig config;
  config.ins.imu_errors = ImuErrors::sample(ImuErrorSpec::navigation_grade(), 1);
  AvionicsSuite suite(stations, stations.all_approaches(), config);
  const double lat0 = 50.0379 * kDegToRad, lon0 = 8.0 * kDegToRad;
  std::vector<std::uint32_t> vhf;
  std::uint32_t ndb = 0;
  tuned.clear();
  for (const auto& hit : db.within(lat0, lon0, 60.0 * fedsim::units::kNmToM)) {
    const Navaid& n = hit.navaid;
    const bool is_ndb = n.type == NavaidType::kNdb || n.type == NavaidType::kNdbDme;
    if (is_ndb && ndb == 0) {
      ndb = n.frequency_khz;
      tuned += "ADF " + n.ident + " ";
    } else if (!is_ndb && vhf.size() < 2 && n.frequency_khz >= 108000) {
      vhf.push_back(n.frequency_khz);
      tuned += "NAV" + std::to_string(vhf.size()) + " " + n.ident + " ";
    }
  }
  for (std::size_t i = 0; i < vhf.size(); ++i) suite.radios().nav[i] = {vhf[i], 0.0};
  suite.radios().adf_khz = ndb;
  suite.failures().gps_denied = !gps;
  suite.failures().ins = !ins;
  AvionicsTruth truth;
  truth.altitude_msl_m = 914.4;
  truth.velocity_ned_mps = {0.0, 50.0, 0.0};
  truth.euler = {0.0, 0.0, fedsim::units::kHalfPi};
  truth.q_ned_from_body = fedsim::quaternion_from_euler(truth.euler);
  truth.true_airspeed_mps = 50.0;
  truth.specific_force_body_mps2 = {0.0, 0.0, -fedsim::units::kStandardGravityMps2};
  const double dt = 0.02;
  const auto at = [&](int frame) {
    truth.lat_rad = lat0;
    truth.lon_rad = lon0 + 50.0 * dt * frame / (6378137.0 * std::cos(lat0));
    return truth;
  };
  suite.align(at(0));
  return time_queries(frames, [&](int i) { suite.step(at(i + 1), dt, dt * (i + 1)); });
}

int main(int argc, char** argv) {
  CLI::App app{"fedsim-bench-navdb: navigation database query times"};
  std::string db_path = fedsim::nav::default_database_path();
  int queries = 5000;
  std::uint64_t seed = 1;
  app.add_option("--db", db_path, "database")->capture_default_str();
  app.add_option("--queries", queries, "queries per measurement")->check(fedsim::util::FiniteRange(100, 10000000));
  app.add_option("--seed", seed, "random seed")->capture_default_str();
  CLI11_PARSE(app, argc, argv);

  try {
    const Stats open = time_queries(200, [&](int) { NavDatabase::open(db_path); });
    const NavDatabase db = NavDatabase::open(db_path);
    const auto all = db.all_navaids();
    std::vector<std::uint32_t> frequencies;
    std::vector<std::string> idents;
    for (const auto& n : all) {
      if (n.frequency_khz != 0) frequencies.push_back(n.frequency_khz);
      idents.push_back(n.ident);
    }
    const std::size_t distinct_frequencies =
        std::set<std::uint32_t>(frequencies.begin(), frequencies.end()).size();

    std::mt19937_64 random(seed);
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    std::size_t within_hits = 0;
    const double radius_m = 50.0 * fedsim::units::kNmToM;
    const Stats within = time_queries(queries, [&](int) {
      const double lat = (50.0379 + 2.0 * unit(random) - 1.0) * kDegToRad;
      const double lon = (8.5622 + 3.0 * unit(random) - 1.5) * kDegToRad;
      within_hits += db.within(lat, lon, radius_m).size();
    });
    std::size_t nearest_found = 0;
    const Stats nearest = time_queries(queries, [&](int) {
      const double lat = std::asin(2.0 * unit(random) - 1.0);
      const double lon = (360.0 * unit(random) - 180.0) * kDegToRad;
      const auto khz = frequencies[static_cast<std::size_t>(unit(random) * frequencies.size())];
      nearest_found += db.nearest_on_frequency(lat, lon, khz).has_value() ? 1 : 0;
    });
    std::size_t find_hits = 0;
    const Stats find = time_queries(queries, [&](int) {
      find_hits += db.find(idents[static_cast<std::size_t>(unit(random) * idents.size())]).size();
    });

    std::string tuned;
    const Stats suite_all = time_suite_steps(db, queries, true, true, tuned);
    const Stats suite_no_gps = time_suite_steps(db, queries, false, true, tuned);
    const Stats suite_radios = time_suite_steps(db, queries, false, false, tuned);

    const double per_within = static_cast<double>(within_hits) / queries;
    const double per_frequency = static_cast<double>(frequencies.size()) / distinct_frequencies;
    std::printf("fedsim-bench-navdb: %s, %zu navaids, %zu frequencies in use\n", db_path.c_str(),
                all.size(), distinct_frequencies);
    print("open", open, "");
    print("within", within, ", 50 NM around Frankfurt, " + std::to_string(per_within).substr(0, 5) +
                                " stations each");
    print("nearest", nearest, ", anywhere, " + std::to_string(per_frequency).substr(0, 5) +
                                  " stations per frequency on average");
    print("find", find, "");
    print("nav step", suite_all, ", every receiver + GPS + INS + FD, tuned " + tuned);
    print("  no GPS", suite_no_gps, ", GPS denied (its fix skipped)");
    print("  radios", suite_radios, ", radios, markers and FD only");
    std::printf("target: nearest tuned station < 1000 us (p99 %.1f us: %s)\n", nearest.p99_us,
                nearest.p99_us < 1000.0 ? "met" : "NOT MET");
    const nlohmann::json figures = {{"bench", "navdb"},
                                    {"navaids", all.size()},
                                    {"open", to_json(open)},
                                    {"within_50nm_frankfurt", to_json(within)},
                                    {"within_mean_hits", per_within},
                                    {"nearest_on_frequency", to_json(nearest)},
                                    {"nearest_found", nearest_found},
                                    {"find_ident", to_json(find)},
                                    {"find_mean_hits", static_cast<double>(find_hits) / queries},
                                    {"nav_step", to_json(suite_all)},
                                    {"nav_step_without_gps", to_json(suite_no_gps)},
                                    {"nav_step_radios_only", to_json(suite_radios)},
                                    {"seed", seed}};
    std::cout << figures.dump() << std::endl;
    return nearest.p99_us < 1000.0 ? 0 : 1;
  } catch (const std::exception& e) {
    std::cerr << "fedsim-bench-navdb: " << e.what() << '\n';
    return 2;
  }
}
