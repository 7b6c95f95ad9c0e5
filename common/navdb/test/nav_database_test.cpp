// NavDatabase: clear errors for files that are not a navigation database of this schema; the
// R*Tree search equals a brute-force geodesic scan (seeded random stations and queries, dense
// near the antimeridian and both poles); distances and bearings against GeographicLib and
// published figures; nearest-on-frequency against a brute-force scan.
#include "common/navdb/nav_database.hpp"
#include "common/util/build_paths.hpp"
#include "common/navdb/nav_schema.hpp"
#include "common/units/units.hpp"
#include "navdb_test_support.hpp"

#include <GeographicLib/Geodesic.hpp>
#include <sqlite3.h>

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <random>
#include <set>

namespace fedsim::nav {
namespace {

using test::build_database;
using test::kNavaidHeader;
using test::kRunwayHeader;
using test::temp_path;
using units::kDegToRad;
using units::kRadToDeg;

std::string open_error(const std::string& path) {
  try {
    NavDatabase::open(path);
  } catch (const std::runtime_error& e) {
    return e.what();
  }
  return "";
}

void expect_error(const std::string& path, const std::string& part) {
  const std::string message = open_error(path);
  EXPECT_NE(message.find(path), std::string::npos) << message;
  EXPECT_NE(message.find(part), std::string::npos) << message;
}

/// A navaids.csv row of a VOR at a position (frequency 113.00 + id mod 100 x 50 kHz).
std::string vor_row(int id, double lat_deg, double lon_deg, std::uint32_t khz) {
  char row[256];
  std::snprintf(row, sizeof row,
                "%d,f,V%d,Station %d,VOR,%u,%.9f,%.9f,100,US,,,,,,,10.0,BOTH,HIGH,\n", id, id, id,
                khz, lat_deg, lon_deg);
  return row;
}

std::string fixed9(double value) {
  char text[32];
  std::snprintf(text, sizeof text, "%.9f", value);
  return text;
}

std::string small_database(const std::string& name) {
  const std::string path = temp_path(name);
  build_database(path, kNavaidHeader + vor_row(1, 10.0, 20.0, 113000), kRunwayHeader);
  return path;
}

void run_sql(const std::string& path, const char* sql) {
  sqlite3* db = nullptr;
  ASSERT_EQ(sqlite3_open(path.c_str(), &db), SQLITE_OK);
  ASSERT_EQ(sqlite3_exec(db, sql, nullptr, nullptr, nullptr), SQLITE_OK) << sqlite3_errmsg(db);
  sqlite3_close(db);
}

// ---- open(): errors ---------------------------------------------------------------------------

TEST(NavDatabaseOpen, MissingFile) {
  expect_error(temp_path("navdb_no_such_file.sqlite"), "no such file");
}

TEST(NavDatabaseOpen, RandomBytesAreNotSqlite) {
  const std::string path = temp_path("navdb_random_bytes.sqlite");
  std::mt19937_64 random(20260822);
  std::ofstream out(path, std::ios::binary);
  for (int i = 0; i < 65536; ++i) out.put(static_cast<char>(random() & 0xff));
  out.close();
  expect_error(path, "not an SQLite database");
}

TEST(NavDatabaseOpen, SqliteWithoutTheSchema) {
  const std::string path = temp_path("navdb_other.sqlite");
  std::filesystem::remove(path);
  run_sql(path, "CREATE TABLE something (x INTEGER)");
  expect_error(path, "not a fedsim navigation database (no table 'meta')");
}

TEST(NavDatabaseOpen, AnotherSchemaVersion) {
  const std::string path = small_database("navdb_version.sqlite");
  EXPECT_NO_THROW(NavDatabase::open(path));  // control: the database as written opens
  run_sql(path, "UPDATE meta SET value = '0' WHERE key = 'schema_version'");
  expect_error(path, "schema version 0, but this program reads version 1; rebuild it");
  run_sql(path, "DELETE FROM meta WHERE key = 'schema_version'");
  expect_error(path, "no schema_version");
}

TEST(NavDatabaseOpen, ATruncatedDatabase) {
  const std::string path = small_database("navdb_truncated.sqlite");
  std::filesystem::resize_file(path, 1000);  // the header page survives, the rest does not
  EXPECT_FALSE(open_error(path).empty());
}

TEST(NavDatabaseOpen, DefaultPathIsTheBuiltDatabaseUnlessTheEnvironmentNamesOne) {
  const char* saved = std::getenv("FEDSIM_NAVDB");
  const std::string saved_value = saved ? saved : "";
  unsetenv("FEDSIM_NAVDB");
  EXPECT_EQ(default_database_path(), fedsim::util::navdb_file());
  setenv("FEDSIM_NAVDB", "/somewhere/else.sqlite", 1);
  EXPECT_EQ(default_database_path(), "/somewhere/else.sqlite");
  if (saved) {
    setenv("FEDSIM_NAVDB", saved_value.c_str(), 1);
  } else {
    unsetenv("FEDSIM_NAVDB");
  }
}

// ---- distances, bearings ----------------------------------------------------------------------

TEST(NavDatabaseGeodesy, DistanceAndBearingMatchGeographicLibAndPublishedFigures) {
  // JFK and LHR as in GeographicLib's example-Geodesic.cpp: 5551.76 km.
  const std::string path = temp_path("navdb_geodesy.sqlite");
  build_database(path,
                 kNavaidHeader + vor_row(1, 51.6, -0.5, 113000) + vor_row(2, 0.0, 1.0, 113050) +
                     vor_row(3, 1.0, 0.0, 113100),
                 kRunwayHeader);
  const NavDatabase db = NavDatabase::open(path);
  const auto far = db.within(40.6 * kDegToRad, -73.8 * kDegToRad, 6000e3);
  ASSERT_EQ(far.size(), 1u);
  EXPECT_NEAR(far[0].distance_m / 1000.0, 5551.76, 0.005);
  double s12 = 0.0, azi1 = 0.0, azi2 = 0.0;
  GeographicLib::Geodesic::WGS84().Inverse(40.6, -73.8, 51.6, -0.5, s12, azi1, azi2);
  EXPECT_NEAR(far[0].distance_m, s12, 1e-6);
  EXPECT_NEAR(far[0].bearing_true_rad * kRadToDeg, azi1, 1e-9);
  // From the origin: station 2 due east on the equator (bearing 90 deg, a/1 deg of arc), station
  // 3 due north (bearing 0, the meridian arc of 1 deg: 110.574 km, NIMA TR8350.2).
  const auto near = db.within(0.0, 0.0, 200e3);
  ASSERT_EQ(near.size(), 2u);
  EXPECT_EQ(near[0].navaid.id, 3);
  EXPECT_NEAR(near[0].bearing_true_rad, 0.0, 1e-12);
  EXPECT_NEAR(near[0].distance_m, 110574.4, 0.5);
  EXPECT_EQ(near[1].navaid.id, 2);
  EXPECT_NEAR(near[1].bearing_true_rad * kRadToDeg, 90.0, 1e-9);
  EXPECT_NEAR(near[1].distance_m, 6378137.0 * kDegToRad, 1e-3);
}

// ---- R*Tree search vs brute force -------------------------------------------------------------

struct Station {
  int id;
  double lat_deg;
  double lon_deg;
  std::uint32_t khz;
};

class RandomStations : public testing::Test {
 protected:
  static void SetUpTestSuite() {
    std::mt19937_64 random(42);
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    auto add = [&](double lat_deg, double lon_deg) {
      const int id = static_cast<int>(stations_.size()) + 1;
      const std::uint32_t khz = 112300 + 50 * static_cast<std::uint32_t>(id % 20);
      // The brute force uses the coordinates as written to the CSV (9 decimals).
      stations_.push_back(Station{id, std::stod(fixed9(lat_deg)), std::stod(fixed9(lon_deg)), khz});
    };
    for (int i = 0; i < 1500; ++i) {  // uniform on the sphere
      add(std::asin(2.0 * unit(random) - 1.0) * kRadToDeg, 360.0 * unit(random) - 180.0);
    }
    for (int i = 0; i < 600; ++i) add(87.0 + 3.0 * unit(random), 360.0 * unit(random) - 180.0);
    for (int i = 0; i < 600; ++i) add(-87.0 - 3.0 * unit(random), 360.0 * unit(random) - 180.0);
    for (int i = 0; i < 1200; ++i) {  // a band across the antimeridian
      const double lon = 179.0 + 2.0 * unit(random);
      add(120.0 * unit(random) - 60.0, lon > 180.0 ? lon - 360.0 : lon);
    }
    std::string csv = kNavaidHeader;
    for (const auto& s : stations_) csv += vor_row(s.id, s.lat_deg, s.lon_deg, s.khz);
    path_ = temp_path("navdb_random.sqlite");
    build_database(path_, csv, kRunwayHeader);
  }

  static std::set<int> brute_force(double lat_deg, double lon_deg, double radius_m) {
    std::set<int> ids;
    for (const auto& s : stations_) {
      double d = 0.0;
      GeographicLib::Geodesic::WGS84().Inverse(lat_deg, lon_deg, s.lat_deg, s.lon_deg, d);
      if (d <= radius_m) ids.insert(s.id);
    }
    return ids;
  }

  static std::vector<Station> stations_;
  static std::string path_;
};
std::vector<Station> RandomStations::stations_;
std::string RandomStations::path_;

TEST_F(RandomStations, WithinEqualsBruteForce) {
  const NavDatabase db = NavDatabase::open(path_);
  std::mt19937_64 random(7);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  int queries_with_hits = 0, antimeridian_both_sides = 0, pole_hits = 0;
  for (int q = 0; q < 600; ++q) {
    double lat = std::asin(2.0 * unit(random) - 1.0) * kRadToDeg;
    double lon = 360.0 * unit(random) - 180.0;
    if (q % 3 == 1) lon = (unit(random) < 0.5 ? 179.5 : -179.5) + unit(random) * 0.5 * (lon > 0 ? 1 : -1);
    if (q % 3 == 2) lat = (q % 2 ? 1.0 : -1.0) * (86.0 + 4.0 * unit(random));
    const double radius_m = std::exp(std::log(2e3) + unit(random) * std::log(1500.0));  // 2-3000 km
    const auto hits = db.within(lat * kDegToRad, lon * kDegToRad, radius_m);
    std::set<int> ids;
    bool east = false, west = false;
    for (std::size_t i = 0; i < hits.size(); ++i) {
      ids.insert(static_cast<int>(hits[i].navaid.id));
      if (i > 0) {
        EXPECT_LE(hits[i - 1].distance_m, hits[i].distance_m);  // nearest first
      }
      EXPECT_LE(hits[i].distance_m, radius_m);
      east = east || hits[i].navaid.position.lon_rad > 0.0;
      west = west || hits[i].navaid.position.lon_rad < 0.0;
    }
    EXPECT_EQ(ids.size(), hits.size()) << "a station twice";
    ASSERT_EQ(ids, brute_force(lat, lon, radius_m))
        << "query " << q << " at " << lat << ", " << lon << " radius " << radius_m;
    queries_with_hits += hits.empty() ? 0 : 1;
    if (std::abs(lon) > 179.0 && east && west) ++antimeridian_both_sides;
    if (std::abs(lat) > 86.0 && !hits.empty()) ++pole_hits;
  }
  // The cases that matter did occur (the comparison is not vacuous).
  std::printf("%d of 600 queries with hits, %d across the antimeridian, %d near a pole\n",
              queries_with_hits, antimeridian_both_sides, pole_hits);
  EXPECT_GT(queries_with_hits, 250);
  EXPECT_GT(antimeridian_both_sides, 50);
  EXPECT_GT(pole_hits, 100);
}

TEST_F(RandomStations, NearestOnFrequencyEqualsBruteForce) {
  const NavDatabase db = NavDatabase::open(path_);
  std::mt19937_64 random(11);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  for (int q = 0; q < 300; ++q) {
    const double lat = std::asin(2.0 * unit(random) - 1.0) * kRadToDeg;
    const double lon = 360.0 * unit(random) - 180.0;
    const std::uint32_t khz = 112300 + 50 * static_cast<std::uint32_t>(q % 20);
    int best_id = 0;
    double best_m = INFINITY;
    for (const auto& s : stations_) {
      if (s.khz != khz) continue;
      double d = 0.0;
      GeographicLib::Geodesic::WGS84().Inverse(lat, lon, s.lat_deg, s.lon_deg, d);
      if (d < best_m) best_m = d, best_id = s.id;
    }
    const auto hit = db.nearest_on_frequency(lat * kDegToRad, lon * kDegToRad, khz);
    ASSERT_TRUE(hit.has_value());
    EXPECT_EQ(hit->navaid.id, best_id);
    EXPECT_NEAR(hit->distance_m, best_m, 1e-6);
    EXPECT_EQ(hit->navaid.frequency_khz, khz);
  }
  EXPECT_FALSE(db.nearest_on_frequency(0.0, 0.0, 117950).has_value());  // nobody on it
}

TEST_F(RandomStations, QueriesCheckTheirArguments) {
  const NavDatabase db = NavDatabase::open(path_);
  EXPECT_THROW(db.within(std::nan(""), 0.0, 1e3), std::invalid_argument);
  EXPECT_THROW(db.within(0.0, 0.0, -1.0), std::invalid_argument);
  EXPECT_THROW(db.within(2.0, 0.0, 1e3), std::invalid_argument);
  EXPECT_THROW(db.nearest_on_frequency(0.0, INFINITY, 113000), std::invalid_argument);
  EXPECT_THROW(db.on_frequency(0), std::invalid_argument);
}

}  // namespace
}  // namespace fedsim::nav
