// The builder reports every bad row of the fixture CSVs (common/navdb/test/data) by file and
// line, skips it, keeps the good rows, and refuses sources it cannot read.
#include "common/navdb/nav_database.hpp"
#include "common/navdb/nav_database_builder.hpp"
#include "common/navdb/nav_types.hpp"
#include "common/units/units.hpp"
#include "navdb_test_support.hpp"

#include <GeographicLib/Geodesic.hpp>

#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>

namespace fedsim::nav {
namespace {

using test::build_fixture_database;
using test::temp_path;

/// The problems (errors, or warnings) reported on one line of one file.
std::vector<std::string> problems_on(const BuildReport& report, const std::string& origin,
                                     int line, bool warning = false) {
  std::vector<std::string> out;
  for (const auto& p : report.problems) {
    if (p.origin == origin && p.line == line && p.warning == warning) out.push_back(p.text);
  }
  return out;
}

bool mentions(const std::vector<std::string>& texts, const std::string& part) {
  return std::any_of(texts.begin(), texts.end(),
                     [&](const std::string& t) { return t.find(part) != std::string::npos; });
}

struct ExpectedProblem {
  int line;
  std::string part;  // a part of one of the line's error texts
};

/// Every listed line of `origin` has an error mentioning its part.
void expect_problems(const BuildReport& report, const std::string& origin,
                     const std::vector<ExpectedProblem>& expected) {
  for (const ExpectedProblem& e : expected) {
    EXPECT_TRUE(mentions(problems_on(report, origin, e.line), e.part))
        << origin << ":" << e.line << " lacks '" << e.part << "'";
  }
}

class FixtureBuild : public testing::Test {
 protected:
  static void SetUpTestSuite() {
    path_ = temp_path("navdb_fixture.sqlite");
    report_ = build_fixture_database(path_);
  }
  static std::string path_;
  static BuildReport report_;
};
std::string FixtureBuild::path_;
BuildReport FixtureBuild::report_;

TEST_F(FixtureBuild, ReportsEachBadNavaidRowByLine) {
  const std::string f = "navaids.csv";
  expect_problems(report_, f,
                  {{4, "navaids.csv:4: column 'frequency_khz': empty"},
                   {5, "column 'latitude_deg': 91.5 is outside"},
                   {6, "unknown type 'LOC'"},
                   {7, "column 'elevation_ft': not a number: 'abc'"},
                   {8, "DME channel 106X pairs with 115900 kHz"},
                   {9, "outside the NDB band"},
                   {10, "ILS localizer frequency"},
                   {11, "93531 already read on line 2"},
                   {12, "18 fields, the header has 20"},
                   {17, "column 'magnetic_variation_deg': empty"}});
  // The redundant dme_frequency_khz of line 15 disagrees with its channel: kept, with a warning.
  EXPECT_TRUE(mentions(problems_on(report_, f, 15, true), "dme_frequency_khz"));
  // Good rows carry no problem (negative control of the line matching).
  for (int good : {2, 3, 13, 14, 15, 16}) EXPECT_TRUE(problems_on(report_, f, good).empty()) << good;
  EXPECT_EQ(report_.navaid_rows, 16u);
  EXPECT_EQ(report_.navaids_skipped, 10u);
  EXPECT_EQ(report_.navaids_kept(), 6u);
}

TEST_F(FixtureBuild, ReportsEachBadRunwayEndByLine) {
  const std::string f = "runways.csv";
  expect_problems(report_, f,
                  {{6, "'le_longitude_deg': empty while the other"},
                   {7, "same position"},
                   {8, "column 'closed': '2' is not 0 or 1"},
                   {9, "runway 09 but the ends' azimuth is 270"},
                   {11, "'le_displaced_threshold_ft': 6000 ft"},
                   {12, "KSFO 28R already read on line 2"}});
  EXPECT_EQ(problems_on(report_, f, 7).size(), 2u);  // both ends at one position
  EXPECT_TRUE(problems_on(report_, f, 10).empty());  // no position: counted, not an error
  for (int good = 2; good <= 5; ++good) EXPECT_TRUE(problems_on(report_, f, good).empty());
  EXPECT_EQ(report_.runway_rows, 11u);
  EXPECT_EQ(report_.runway_ends, 10u);
  EXPECT_EQ(report_.runway_ends_skipped, 10u);
  EXPECT_EQ(report_.runway_rows_skipped, 1u);
  EXPECT_EQ(report_.runway_ends_unpositioned, 2u);
}

TEST_F(FixtureBuild, ReportsEachBadIlsRowByLine) {
  const std::string f = "ils.csv";
  expect_problems(report_, f,
                  {{6, "110.20 MHz is not a localizer frequency"},
                   {7, "no runway end KSFO 99"},
                   {8, "'glide_path_angle_deg': 9.00 is outside"},
                   {9, "from runway 10L's landing direction"},
                   {10, "'course_lat_deg' is not a column"},
                   {11, "a second ILS for KSFO 28R (first on line 4)"}});
  EXPECT_TRUE(problems_on(report_, f, 4).empty());
  EXPECT_TRUE(problems_on(report_, f, 5).empty());
  EXPECT_EQ(report_.ils_rows, 8u);
  EXPECT_EQ(report_.ils_kept, 2u);
  EXPECT_EQ(report_.ils_skipped, 6u);
}

TEST_F(FixtureBuild, TheDatabaseHoldsTheGoodRows) {
  const NavDatabase db = NavDatabase::open(path_);
  EXPECT_EQ(db.all_navaids().size(), 6u);
  EXPECT_EQ(db.meta("schema_version"), "1");
  // A TACAN on an unpaired channel: kept, frequency 0, its channel.
  const auto tacan = db.find("uta");
  ASSERT_EQ(tacan.size(), 1u);
  EXPECT_EQ(tacan[0].type, NavaidType::kTacan);
  EXPECT_EQ(tacan[0].frequency_khz, 0u);
  EXPECT_EQ(tacan[0].dme_channel, "012X");
  // A VOR-DME without a channel: derived from its frequency (113.90 MHz -> 86X).
  const auto derived = db.find("NCH");
  ASSERT_EQ(derived.size(), 1u);
  EXPECT_EQ(derived[0].dme_channel, "086X");
  ASSERT_TRUE(derived[0].dme.has_value());
  EXPECT_DOUBLE_EQ(derived[0].dme->lat_rad, derived[0].position.lat_rad);  // co-located
  // A separate DME antenna keeps its own position and elevation.
  const auto lit = db.find("RDM");
  ASSERT_EQ(lit.size(), 1u);
  ASSERT_TRUE(lit[0].dme.has_value());
  EXPECT_NEAR(lit[0].dme->lat_rad * units::kRadToDeg, 34.68, 1e-12);
  EXPECT_NEAR(lit[0].dme->elevation_m, 310 * units::kFtToM, 1e-9);
  // The one kept end of a row whose other end was skipped, and a closed runway.
  const auto xaaa = db.runway("XAAA", "27");
  ASSERT_TRUE(xaaa.has_value());
  EXPECT_NEAR(xaaa->heading_true_rad * units::kRadToDeg, 270.0, 1e-12);  // the published one
  const auto xfff = db.runway("XFFF", "22");
  ASSERT_TRUE(xfff.has_value());
  EXPECT_TRUE(xfff->closed);
  EXPECT_FALSE(db.runway("XFFF", "04").has_value());
  EXPECT_FALSE(db.runway("XBBB", "09").has_value());
}

TEST_F(FixtureBuild, IlsCarriesItsRunwayThresholdAndSiUnits) {
  const NavDatabase db = NavDatabase::open(path_);
  const auto ils = db.ils("ksfo", "28r");
  ASSERT_TRUE(ils.has_value());
  EXPECT_EQ(ils->ident, "IGWQ");
  EXPECT_EQ(ils->frequency_khz, 111700u);
  EXPECT_EQ(ils->category, "III");
  EXPECT_NEAR(ils->glide_path_angle_rad, 3.0 * units::kDegToRad, 1e-12);
  EXPECT_NEAR(ils->threshold_crossing_height_m, 55 * units::kFtToM, 1e-9);
  EXPECT_NEAR(ils->course_magnetic_rad, 284.0 * units::kDegToRad, 1e-12);
  EXPECT_DOUBLE_EQ(ils->course_width_rad, 0.0);  // by rule
  EXPECT_TRUE(ils->has_dme);
  const auto end = db.runway("KSFO", "28R");
  ASSERT_TRUE(end.has_value());
  EXPECT_DOUBLE_EQ(ils->threshold.lat_rad, end->threshold.lat_rad);
  const auto lower_case_row = db.ils("KSFO", "28L");  // written "ksfo,28l" in the fixture
  ASSERT_TRUE(lower_case_row.has_value());
  EXPECT_EQ(lower_case_row->airport, "KSFO");
  EXPECT_NEAR(lower_case_row->course_width_rad, 5.0 * units::kDegToRad, 1e-12);
  EXPECT_EQ(db.ils_on_frequency(109550).size(), 1u);
  EXPECT_EQ(db.ils_by_ident("igwq").size(), 1u);
  EXPECT_EQ(db.airport_ils("KSFO").size(), 2u);
  EXPECT_FALSE(db.ils("KSFO", "19L").has_value());
}

TEST(NavDatabaseBuilder, DisplacedThresholdLiesAlongTheRunway) {
  // KSFO 28R: end (37.613538, -122.35716), 300 ft displaced toward 10L (37.628742, -122.39341).
  const std::string path = temp_path("navdb_threshold.sqlite");
  build_fixture_database(path);
  const auto end = NavDatabase::open(path).runway("KSFO", "28R");
  ASSERT_TRUE(end.has_value());
  const auto& g = GeographicLib::Geodesic::WGS84();
  double along_m = 0.0, azimuth_deg = 0.0, azimuth2_deg = 0.0;
  g.Inverse(37.613538, -122.35716, end->threshold.lat_rad * units::kRadToDeg,
            end->threshold.lon_rad * units::kRadToDeg, along_m, azimuth_deg, azimuth2_deg);
  EXPECT_NEAR(along_m, 300 * units::kFtToM, 1e-6);
  double to_10l_m = 0.0, to_10l_deg = 0.0;
  g.Inverse(37.613538, -122.35716, 37.628742, -122.39341, to_10l_m, to_10l_deg, azimuth2_deg);
  EXPECT_NEAR(azimuth_deg, to_10l_deg, 1e-9);
  EXPECT_NEAR(end->heading_true_rad * units::kRadToDeg, to_10l_deg + 360.0, 1e-9);
  EXPECT_NEAR(end->length_m, 11870 * units::kFtToM, 1e-9);  // the published length
  EXPECT_NEAR(end->end.lat_rad * units::kRadToDeg, 37.613538, 1e-12);
  // No displacement: the threshold is the end (negative control).
  const auto ten_left = NavDatabase::open(path).runway("KSFO", "10L");
  ASSERT_TRUE(ten_left.has_value());
  EXPECT_DOUBLE_EQ(ten_left->threshold.lat_rad, ten_left->end.lat_rad);
}

TEST(NavDatabaseBuilder, MissingColumnsAndUnreadableSourcesAreHardErrors) {
  NavDatabaseBuilder builder;
  std::istringstream no_type("id,ident,name\n1,ABC,abc\n");
  EXPECT_THROW(builder.read_navaids(no_type, "short.csv"), csv::CsvError);
  std::istringstream empty("");
  EXPECT_THROW(builder.read_runways(empty, "empty.csv"), csv::CsvError);
  std::istringstream bad;
  bad.setstate(std::ios::badbit);
  EXPECT_THROW(builder.read_navaids(bad, "unreadable.csv"), std::runtime_error);
  try {
    std::istringstream again("id,ident,name\n");
    builder.read_navaids(again, "short.csv");
  } catch (const csv::CsvError& e) {
    EXPECT_NE(std::string(e.what()).find("short.csv: no column"), std::string::npos) << e.what();
  }
}

TEST(NavDatabaseBuilder, WritesAtomically) {
  const std::string path = temp_path("navdb_atomic.sqlite");
  build_fixture_database(path);
  EXPECT_TRUE(std::filesystem::exists(path));
  EXPECT_FALSE(std::filesystem::exists(path + ".partial"));
  // Rebuilding over an open database leaves the reader's file intact (rename, not rewrite).
  const NavDatabase reader = NavDatabase::open(path);
  build_fixture_database(path);
  EXPECT_EQ(reader.find("SFO").size(), 1u);
  EXPECT_EQ(NavDatabase::open(path).find("SFO").size(), 1u);
}

}  // namespace
}  // namespace fedsim::nav
