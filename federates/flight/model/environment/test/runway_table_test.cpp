#include "flight/model/environment/runway_table.hpp"

#include <gtest/gtest.h>

#include <cmath>

namespace fedsim::flight {
namespace {

TEST(RunwayTable, FindsPublishedThresholdsAndAppliesDisplacement) {
  const auto table = RunwayTable::load_default();
  EXPECT_GT(table.size(), 10000u);
  const auto r10l = table.at("KSFO", "10L");  // no displacement: the published end
  EXPECT_NEAR(r10l.threshold_lat_rad * 180 / M_PI, 37.628742, 1e-9);
  EXPECT_NEAR(r10l.heading_rad * 180 / M_PI, 118.0, 1e-9);
  EXPECT_NEAR(r10l.elevation_m, 1.5, 0.05);
  // 28R's landing threshold is displaced 300 ft (91 m) along its heading of 298 deg true.
  const auto r28r = table.at("KSFO", "28R");
  const double dlat_m = (r28r.threshold_lat_rad * 180 / M_PI - 37.613538) * 111000.0;
  EXPECT_NEAR(dlat_m, 91.0 * std::cos(298.0 * M_PI / 180), 2.0);
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

}  // namespace
}  // namespace fedsim::flight
