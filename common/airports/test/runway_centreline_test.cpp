#include "common/airports/runway_centreline.hpp"
#include "common/units/units.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <fstream>

namespace fedsim {
namespace {

constexpr double kDeg = units::kDegToRad;

TEST(RunwayCentreline, ReciprocalRunways) {
  EXPECT_EQ(reciprocal_runway("28R"), "10L");
  EXPECT_EQ(reciprocal_runway("10L"), "28R");
  EXPECT_EQ(reciprocal_runway("19R"), "1L");
  EXPECT_EQ(reciprocal_runway("01"), "19");
  EXPECT_EQ(reciprocal_runway("9C"), "27C");
  EXPECT_EQ(reciprocal_runway("36"), "18");
  EXPECT_EQ(reciprocal_runway("18"), "36");
  EXPECT_THROW(reciprocal_runway("37"), std::invalid_argument);
  EXPECT_THROW(reciprocal_runway("0"), std::invalid_argument);
  EXPECT_THROW(reciprocal_runway("28X"), std::invalid_argument);
  EXPECT_THROW(reciprocal_runway("R"), std::invalid_argument);
  EXPECT_THROW(reciprocal_runway("H1"), std::invalid_argument);
}

// A runway on the equator landing due east, 3000 m long: beyond the threshold is east, left is
// north (1 deg of longitude on the equator is 111,319 m on WGS-84).
TEST(RunwayCentreline, AlongAndLeftOfAnEastboundRunway) {
  const double far_lon_deg = 3000.0 / 111319.49;
  const RunwayCentreline runway(0.0, 0.0, 0.0, far_lon_deg * kDeg);
  EXPECT_NEAR(runway.length_m(), 3000.0, 0.1);
  EXPECT_NEAR(runway.beyond_threshold_m(0.0, 0.0), 0.0, 1e-9);
  EXPECT_NEAR(runway.left_m(0.0, 0.0), 0.0, 1e-9);
  EXPECT_NEAR(runway.beyond_threshold_m(0.0, far_lon_deg * kDeg), runway.length_m(), 1e-9);
  const double north_100m = 100.0 / 110574.0 * kDeg;  // 1 deg of latitude at the equator: 110,574 m
  EXPECT_NEAR(runway.left_m(north_100m, 0.0), 100.0, 0.1);
  EXPECT_NEAR(runway.left_m(-north_100m, 0.0), -100.0, 0.1);
  EXPECT_NEAR(runway.beyond_threshold_m(north_100m, 0.0), 0.0, 0.01);
  EXPECT_NEAR(runway.beyond_threshold_m(0.0, -far_lon_deg * kDeg), -3000.0, 0.1);  // short of it
  // The opposite direction: left is now south.
  const RunwayCentreline westbound(0.0, far_lon_deg * kDeg, 0.0, 0.0);
  EXPECT_NEAR(westbound.left_m(north_100m, far_lon_deg * kDeg), -100.0, 0.1);
}

TEST(RunwayCentreline, CoincidentEndsAreRejected) {
  EXPECT_THROW(RunwayCentreline(0.5, 0.5, 0.5, 0.5), std::invalid_argument);
}

// KSFO 28R (data/nav/runways.csv): 10L's end 37.628742 N 122.39341 W; 3618 m end to end, 28R's
// threshold displaced 91 m: 3527 m from threshold to the far threshold.
TEST(RunwayCentreline, FromTheTableLandingOnKsfo28R) {
  const RunwayTable table = RunwayTable::load_default();
  const RunwayCentreline runway = RunwayCentreline::from_table(table, "KSFO", "28R");
  EXPECT_NEAR(runway.length_m(), 3618.0 - 91.0, 2.0);
  const RunwayEnd landing = table.at("KSFO", "28R");
  EXPECT_NEAR(runway.beyond_threshold_m(landing.threshold_lat_rad, landing.threshold_lon_rad), 0.0, 1e-9);
  EXPECT_NEAR(runway.left_m(37.628742 * kDeg, -122.39341 * kDeg), 0.0, 1e-6);
  // KSFO spells its one-digit ends 1L/19R; the reciprocal of 19R is found either way.
  EXPECT_NEAR(RunwayCentreline::from_table(table, "KSFO", "19R").length_m(), 2000.0, 1000.0);
}

TEST(RunwayCentreline, FromTheTableNamesTheMissingEnd) {
  const RunwayTable table = RunwayTable::load_default();
  try {
    RunwayCentreline::from_table(table, "KCOS", "17L");  // the table has no 35R at KCOS
    FAIL() << "a runway without its opposite end was accepted";
  } catch (const std::invalid_argument& e) {
    EXPECT_EQ(std::string(e.what()),
              "KCOS 17L: no opposite end 35R in the runway table (the centreline needs both ends)");
  }
  try {
    RunwayCentreline::from_table(table, "KSFO", "27");
    FAIL() << "an unknown landing end was accepted";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("has no runway '27'"), std::string::npos) << e.what();
  }
}

// A one-digit end may be spelt 9 or 09; ends that coincide are named by airport and runway.
TEST(RunwayCentreline, FromTheTableTriesBothSpellingsAndRejectsCoincidentEnds) {
  const std::string path = testing::TempDir() + "/centreline_runways.csv";
  {
    std::ofstream out(path);
    out << "airport,runway,threshold_lat_deg,threshold_lon_deg,elevation_m,heading_true_deg,"
           "length_m,displaced_threshold_m\n"
        << "KAAA,09,0.0,0.0,5.0,90,3000,0\n"
        << "KAAA,27,0.0,0.03,5.0,270,3000,0\n"
        << "KBBB,9,0.0,0.0,5.0,90,3000,0\n"
        << "KBBB,27,0.0,0.03,5.0,270,3000,0\n"
        << "KCCC,18,1.0,1.0,5.0,180,3000,0\n"
        << "KCCC,36,1.0,1.0,5.0,360,3000,0\n";
  }
  const RunwayTable table = RunwayTable::load_file(path);
  std::remove(path.c_str());
  EXPECT_NEAR(RunwayCentreline::from_table(table, "KAAA", "27").length_m(), 0.03 * 111319.49, 0.5);
  EXPECT_NEAR(RunwayCentreline::from_table(table, "KBBB", "27").length_m(), 0.03 * 111319.49, 0.5);
  try {
    RunwayCentreline::from_table(table, "KCCC", "18");
    FAIL() << "coincident ends were accepted";
  } catch (const std::invalid_argument& e) {
    EXPECT_EQ(std::string(e.what()), "KCCC 18: the two ends coincide");
  }
}

}  // namespace
}  // namespace fedsim
