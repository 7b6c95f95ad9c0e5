#include "common/airports/runway_table.hpp"
#include "common/units/units.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <fstream>

namespace fedsim {
namespace {

TEST(RunwayTable, FindsPublishedThresholdsAndAppliesDisplacement) {
  const auto table = RunwayTable::load_default();
  EXPECT_GT(table.size(), 10000u);
  const auto r10l = table.at("KSFO", "10L");  // no displacement: the published end
  EXPECT_NEAR(r10l.threshold_lat_rad * units::kRadToDeg, 37.628742, 1e-9);
  EXPECT_NEAR(r10l.heading_rad * units::kRadToDeg, 118.0, 1e-9);
  EXPECT_NEAR(r10l.elevation_m, 1.5, 0.05);
  // 28R's landing threshold is displaced 300 ft (91 m) along its heading of 298 deg true.
  const auto r28r = table.at("KSFO", "28R");
  const double dlat_m = (r28r.threshold_lat_rad * units::kRadToDeg - 37.613538) * 111000.0;
  EXPECT_NEAR(dlat_m, 91.0 * std::cos(298.0 * units::kDegToRad), 2.0);
}

TEST(RunwayTable, UnknownRunwayListsWhatTheAirportHas) {
  const auto table = RunwayTable::load_default();
  EXPECT_FALSE(table.find("KSFO", "99X").has_value());
  try {
    table.at("KSFO", "99X");
    FAIL();
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("28R"), std::string::npos) << e.what();
  }
  EXPECT_THROW(table.at("ZZZZ", "01"), std::invalid_argument);
}

TEST(RunwayTable, ABadRowIsAnErrorNamingFileLineAndColumn) {
  const std::string path = testing::TempDir() + "/bad_runways.csv";
  {
    std::ofstream out(path);
    out << "airport,runway,threshold_lat_deg,threshold_lon_deg,elevation_m,heading_true_deg,"
           "length_m,displaced_threshold_m\n"
        << "KAAA,09,10.0,20.0,5.0,90,3000,0\n"
        << "KAAA,27,10.0,20.1,5.0,270,3000,nan\n";
  }
  try {
    RunwayTable::load_file(path);
    FAIL() << "a NaN displacement was accepted";
  } catch (const std::runtime_error& e) {
    EXPECT_EQ(std::string(e.what()),
              path + ":3: column 'displaced_threshold_m': not a number: 'nan'");
  }
  std::remove(path.c_str());
}

}  // namespace
}  // namespace fedsim
