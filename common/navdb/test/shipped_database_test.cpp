// The database the build makes from the shipped OurAirports files (util::navdb_file()): real
// stations and runways against published facts (FAA Chart Supplement, airport diagram).
#include "common/navdb/nav_database.hpp"
#include "common/util/build_paths.hpp"
#include "common/navdb/nav_types.hpp"
#include "common/units/units.hpp"

#include <GeographicLib/Geodesic.hpp>

#include <gtest/gtest.h>

#include <algorithm>

namespace fedsim::nav {
namespace {

using units::kDegToRad;
using units::kRadToDeg;

// KSFO airport reference point (FAA 5010): 37-37-08.3N 122-22-29.6W.
constexpr double kKsfoLatDeg = 37.0 + 37.0 / 60.0 + 8.3 / 3600.0;
constexpr double kKsfoLonDeg = -(122.0 + 22.0 / 60.0 + 29.6 / 3600.0);

const NavDatabase& shipped() {
  static const NavDatabase db = NavDatabase::open(fedsim::util::navdb_file());
  return db;
}

TEST(ShippedDatabase, SanFranciscoVorDme) {
  const auto stations = shipped().find("sfo");
  const auto sfo = std::find_if(stations.begin(), stations.end(),
                                [](const Navaid& n) { return n.country == "US"; });
  ASSERT_NE(sfo, stations.end());
  EXPECT_EQ(sfo->type, NavaidType::kVorDme);
  EXPECT_EQ(sfo->frequency_khz, 115800u);  // 115.80 MHz, channel 105X (Chart Supplement)
  EXPECT_EQ(sfo->dme_channel, "105X");
  EXPECT_EQ(sfo->airport, "KSFO");
  EXPECT_NEAR(sfo->magnetic_variation_rad * kRadToDeg, 14.423, 1e-9);
  EXPECT_NEAR(sfo->slaved_variation_rad * kRadToDeg, 17.001, 1e-9);
  // On the airport: within 2 km of the reference point.
  const auto near = shipped().within(kKsfoLatDeg * kDegToRad, kKsfoLonDeg * kDegToRad, 2000.0);
  EXPECT_TRUE(std::any_of(near.begin(), near.end(),
                          [&](const NavaidHit& h) { return h.navaid.id == sfo->id; }));
  // Tuned to 115.80 at KSFO, the receiver finds SFO; tuned to it over New York, another station
  // (negative control: the frequency is reused).
  const auto tuned = shipped().nearest_on_frequency(kKsfoLatDeg * kDegToRad,
                                                    kKsfoLonDeg * kDegToRad, 115800);
  ASSERT_TRUE(tuned.has_value());
  EXPECT_EQ(tuned->navaid.id, sfo->id);
  EXPECT_LT(tuned->distance_m, 1000.0);
  const auto elsewhere = shipped().nearest_on_frequency(40.64 * kDegToRad, -73.78 * kDegToRad,
                                                        115800);
  ASSERT_TRUE(elsewhere.has_value());
  EXPECT_NE(elsewhere->navaid.id, sfo->id);
}

TEST(ShippedDatabase, Ksfo28RRunwayEnd) {
  const auto end = shipped().runway("KSFO", "28R");
  ASSERT_TRUE(end.has_value());
  // OurAirports' 28R end, and FAA: 11,870 ft x 200 ft, 300 ft displaced threshold, 13 ft.
  EXPECT_NEAR(end->end.lat_rad * kRadToDeg, 37.613538, 1e-9);
  EXPECT_NEAR(end->end.lon_rad * kRadToDeg, -122.35716, 1e-9);
  EXPECT_NEAR(end->length_m, 11870.0 * units::kFtToM, 1e-6);
  EXPECT_NEAR(end->width_m, 200.0 * units::kFtToM, 1e-6);
  EXPECT_NEAR(end->displaced_threshold_m, 300.0 * units::kFtToM, 1e-6);
  EXPECT_NEAR(end->threshold.elevation_m, 13.0 * units::kFtToM, 1e-9);
  EXPECT_TRUE(end->lighted);
  EXPECT_FALSE(end->closed);
  // Landing direction 298 deg true (284 magnetic + 14 E on the FAA diagram), to within 1 deg.
  EXPECT_NEAR(end->heading_true_rad * kRadToDeg, 298.0, 1.0);
  // The four runways, eight ends.
  EXPECT_EQ(shipped().airport_runways("ksfo").size(), 8u);
}

TEST(ShippedDatabase, StationsNearThePoleAndTheAntimeridian) {
  // ZSP, the TACAN at Amundsen-Scott South Pole station (OurAirports: -89.9952, 120.929).
  const auto pole = shipped().within(-90.0 * kDegToRad, 0.0, 50e3);
  EXPECT_TRUE(std::any_of(pole.begin(), pole.end(),
                          [](const NavaidHit& h) { return h.navaid.ident == "ZSP"; }));
  // MT NDB (-16.6883, -179.881) and LB NDB (-16.4183, 179.315), Fiji: 64 km apart across 180.
  const auto fiji = shipped().within(-16.5 * kDegToRad, 179.9 * kDegToRad, 100e3);
  const auto has = [&](const char* ident) {
    return std::any_of(fiji.begin(), fiji.end(),
                       [&](const NavaidHit& h) { return h.navaid.ident == ident; });
  };
  EXPECT_TRUE(has("MT"));
  EXPECT_TRUE(has("LB"));
}

TEST(ShippedDatabase, KeepsAlmostEveryStationOfEveryType) {
  const NavDatabase& db = shipped();
  EXPECT_EQ(db.meta("schema_version"), "1");
  const auto all = db.all_navaids();
  EXPECT_GT(all.size(), 10800u);  // of 11,008 rows
  std::map<NavaidType, int> by_type;
  for (const auto& n : all) ++by_type[n.type];
  EXPECT_EQ(by_type.size(), 7u);
  EXPECT_GT(by_type[NavaidType::kNdb], 6400);
  EXPECT_GT(by_type[NavaidType::kVorDme], 2500);
}

}  // namespace
}  // namespace fedsim::nav
