// Light layouts against ICAO Annex 14 Vol I Chapter 5.3's figures: approach systems, edge-light
// colours, centreline colour coding, PAPI settings.
#include "visual/model/light_layout.hpp"

#include "common/units/units.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <set>

namespace fedsim::visual {
namespace {

using units::kDegToRad;

bool is_red(const Eigen::Vector3f& c) { return c.x() > 0.9f && c.y() < 0.3f; }
bool is_yellow(const Eigen::Vector3f& c) { return c.x() > 0.9f && c.y() > 0.6f && c.z() < 0.3f; }
bool is_white(const Eigen::Vector3f& c) { return c.minCoeff() > 0.8f; }

TEST(ApproachLights, IcaoCatICentrelineIsDistanceCoded) {
  EndLightingInput in;
  in.approach = ApproachLighting::kIcaoCatI;
  std::map<double, int> sources;  // along -> centreline sources there
  std::vector<double> crossbar;
  for (const auto& s : approach_lights(in)) {
    if (s.role == LightRole::kApproachCentreline) ++sources[s.along_m];
    if (s.role == LightRole::kApproachCrossbar) {
      EXPECT_DOUBLE_EQ(s.along_m, -300.0);
      crossbar.push_back(s.right_m);
    }
  }
  ASSERT_EQ(sources.size(), 30u);  // every 30 m from 30 m to 900 m
  EXPECT_EQ(sources.begin()->first, -900.0);
  EXPECT_EQ(sources.rbegin()->first, -30.0);
  EXPECT_EQ(sources[-30.0], 1);
  EXPECT_EQ(sources[-300.0], 1);
  EXPECT_EQ(sources[-330.0], 2);
  EXPECT_EQ(sources[-600.0], 2);
  EXPECT_EQ(sources[-630.0], 3);
  EXPECT_EQ(sources[-900.0], 3);
  // The crossbar 30 m long, a gap of at most 6 m either side of the centreline.
  const auto [lo, hi] = std::minmax_element(crossbar.begin(), crossbar.end());
  EXPECT_DOUBLE_EQ(*hi - *lo, 30.0);
  for (double y : crossbar) {  // symmetric about the centreline
    EXPECT_EQ(std::count(crossbar.begin(), crossbar.end(), -y), 1) << y;
  }
  double inner = 1e9;
  for (double y : crossbar) inner = std::min(inner, std::abs(y));
  EXPECT_LE(inner, 6.0);
}

TEST(ApproachLights, CatIISideRowsAreRedAndOnlyInTheInner270m) {
  EndLightingInput in;
  in.approach = ApproachLighting::kIcaoCatIIorIII;
  in.touchdown_zone_gauge_m = 18.0;
  std::set<double> side_rows, crossbars;
  for (const auto& s : approach_lights(in)) {
    if (s.role == LightRole::kApproachSideRow) {
      side_rows.insert(s.along_m);
      EXPECT_TRUE(is_red(s.colour_rgb));
      EXPECT_GE(std::abs(s.right_m), 9.0);  // on the touchdown-zone gauge
    }
    if (s.role == LightRole::kApproachCrossbar) crossbars.insert(s.along_m);
  }
  EXPECT_EQ(side_rows.size(), 9u);
  EXPECT_EQ(*side_rows.begin(), -270.0);
  EXPECT_EQ(*side_rows.rbegin(), -30.0);
  EXPECT_EQ(crossbars, (std::set<double>{-300.0, -150.0}));
  // No approach lighting: nothing (negative control).
  in.approach = ApproachLighting::kNone;
  EXPECT_TRUE(approach_lights(in).empty());
}

TEST(RunwayLights, EdgeLightsYellowInTheCautionZoneRedBeforeADisplacedThreshold) {
  EndLightingInput in;
  in.width_m = 45.0;
  in.threshold_to_stop_end_m = 3000.0;
  in.runway_start_m = -200.0;
  std::vector<double> along;
  for (double x = -200.0; x <= 3000.0; x += 40.0) along.push_back(x);
  for (const auto& s : edge_lights(in, along)) {
    if (s.along_m < 0.0) {
      EXPECT_TRUE(is_red(s.colour_rgb)) << s.along_m;
    } else if (s.along_m > 3000.0 - 600.0) {  // 600 m < a third of 3200 m
      EXPECT_TRUE(is_yellow(s.colour_rgb)) << s.along_m;
    } else {
      EXPECT_TRUE(is_white(s.colour_rgb)) << s.along_m;
    }
    EXPECT_NEAR(std::abs(s.right_m), 23.1, 1e-9);  // just outside the edge
  }
}

TEST(RunwayLights, CentrelineColourCodingTowardsTheStopEnd) {  // 5.3.12.7
  EndLightingInput in;
  in.width_m = 61.0;
  in.threshold_to_stop_end_m = 3000.0;
  in.category = ApproachCategory::kPrecisionCatIIorIII;
  const auto lights = centreline_lights(in);
  ASSERT_FALSE(lights.empty());
  int red_in_alternating = 0, white_in_alternating = 0;
  for (const auto& s : lights) {
    const double to_go = 3000.0 - s.along_m;
    if (to_go > 900.0) {
      EXPECT_TRUE(is_white(s.colour_rgb)) << s.along_m;
    }
    if (to_go <= 300.0) {
      EXPECT_TRUE(is_red(s.colour_rgb)) << s.along_m;
    }
    if (to_go > 300.0 && to_go <= 900.0) {
      (is_red(s.colour_rgb) ? red_in_alternating : white_in_alternating)++;
    }
    EXPECT_DOUBLE_EQ(std::fmod(s.along_m, 15.0), 0.0);  // 15 m spacing on CAT II/III
  }
  EXPECT_LE(std::abs(red_in_alternating - white_in_alternating), 1);
  EXPECT_GT(red_in_alternating, 10);
  // CAT I on a 45 m runway: none (5.3.12.2 only asks for them on runways wider than 50 m).
  in.category = ApproachCategory::kPrecisionCatI;
  in.width_m = 45.0;
  EXPECT_TRUE(centreline_lights(in).empty());
}

TEST(PapiLayout, SettingsForAThreeDegreePath) {  // 5.3.6: 3d30', 3d10', 2d50', 2d30'
  EndLightingInput in;
  in.width_m = 45.0;
  in.glide_path_rad = 3.0 * kDegToRad;
  const auto units = papi_units(in);
  ASSERT_EQ(units.size(), 4u);
  const double expected_deg[4] = {3.5, 3.0 + 10.0 / 60.0, 3.0 - 10.0 / 60.0, 2.5};
  for (int k = 0; k < 4; ++k) {
    EXPECT_NEAR(units[k].papi_transition_rad / kDegToRad, expected_deg[k], 1e-5);
    EXPECT_EQ(units[k].beam, BeamKind::kPapi);
    EXPECT_LT(units[k].right_m, 0.0);  // left of the runway
    EXPECT_NEAR(units[k].right_m, -(22.5 + 15.0 + 9.0 * k), 1e-9);
  }
}

}  // namespace
}  // namespace fedsim::visual
