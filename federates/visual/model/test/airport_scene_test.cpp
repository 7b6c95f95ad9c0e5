// The KSFO scene built from its runway records: pairing, geometry against GeographicLib,
// markings and lights where Annex 14 puts them, and clear errors for bad records.
#include "visual/model/airport_scene.hpp"
#include "visual/model/test/test_support.hpp"

#include <GeographicLib/Geodesic.hpp>
#include <gtest/gtest.h>

#include <set>

namespace fedsim::visual {
namespace {

using test::kDegToRad;

TEST(AirportScene, KsfoHasEightEndsOnFourRunways) {
  const Scene scene = build_airport_scene(test::ksfo_runway_ends(), test::ksfo_options());
  std::set<std::string> ends;
  for (const auto& e : scene.runway_ends) ends.insert(e.designator);
  EXPECT_EQ(ends, (std::set<std::string>{"10L", "28R", "10R", "28L", "1L", "19R", "1R", "19L"}));
  EXPECT_TRUE(scene.notes.empty());
  // The ground 0.3 m below the lowest end (10L, 5 ft).
  EXPECT_NEAR(scene.ground_elevation_m, 5.0 * units::kFtToM - 0.3, 1e-9);
  const auto& r28 = scene.runway_ends[scene.find_end("28R")];
  EXPECT_EQ(r28.threshold_stripes, 16);  // 61 m wide
  EXPECT_NEAR(r28.landing_distance_m, (11870.0 - 300.0) * units::kFtToM, 1e-6);
  EXPECT_EQ(r28.approach_lighting, ApproachLighting::kIcaoCatIIorIII);
  EXPECT_EQ(scene.runway_ends[scene.find_end("28L")].approach_lighting,
            ApproachLighting::kIcaoCatI);
}

TEST(AirportScene, ThresholdsWhereTheRecordsPutThem) {
  const Scene scene = build_airport_scene(test::ksfo_runway_ends(), test::ksfo_options());
  const auto& earth = GeographicLib::Geodesic::WGS84();
  for (const char* a_name : {"28R", "1L"}) {
    const auto& a = test::ksfo_end(a_name);
    const auto& info = scene.runway_ends[scene.find_end(a_name)];
    const GeodeticPosition g = scene.frame.geodetic(info.threshold_scene_m);
    double distance = 0.0;
    earth.Inverse(g.lat_rad / kDegToRad, g.lon_rad / kDegToRad, a.threshold.lat_rad / kDegToRad,
                  a.threshold.lon_rad / kDegToRad, distance);
    EXPECT_LT(distance, 0.01) << a_name;
  }
  // Threshold to threshold of 28R and 10L: the geodesic between the records' thresholds (the
  // published length, 11870 ft less 300 ft, is a rounded figure 9 cm off the coordinates).
  const auto p28 = scene.runway_ends[scene.find_end("28R")].threshold_scene_m;
  const auto p10 = scene.runway_ends[scene.find_end("10L")].threshold_scene_m;
  const auto& e28 = test::ksfo_end("28R");
  const auto& e10 = test::ksfo_end("10L");
  double geodesic_m = 0.0;
  earth.Inverse(e28.threshold.lat_rad / kDegToRad, e28.threshold.lon_rad / kDegToRad,
                e10.threshold.lat_rad / kDegToRad, e10.threshold.lon_rad / kDegToRad, geodesic_m);
  const double rise_m = e28.threshold.elevation_m - e10.threshold.elevation_m;
  EXPECT_NEAR((p28 - p10).norm(), std::hypot(geodesic_m, rise_m), 0.01);
  EXPECT_NEAR((p28 - p10).norm(), (11870.0 - 300.0) * units::kFtToM, 0.2);
}

TEST(AirportScene, LightsOfEachKind) {
  const Scene scene = build_airport_scene(test::ksfo_runway_ends(), test::ksfo_options());
  const int r28 = scene.find_end("28R");
  EXPECT_EQ(scene.lights_of(r28, LightRole::kPapi).size(), 4u);
  EXPECT_EQ(scene.lights_of(r28, LightRole::kApproachSideRow).size(), 9u * 6u);
  EXPECT_EQ(scene.lights_of(r28, LightRole::kApproachCentreline).size(), 30u * 5u);
  EXPECT_GT(scene.lights_of(r28, LightRole::kRunwayCentreline).size(), 200u);
  EXPECT_GT(scene.lights_of(r28, LightRole::kTouchdownZone).size(), 100u);
  // Threshold lights: across the 61 m at most 3 m apart; the approach lights before it.
  const auto threshold = scene.lights_of(r28, LightRole::kThreshold);
  EXPECT_GE(threshold.size(), 21u);
  const auto& info = scene.runway_ends[r28];
  const Eigen::Vector3d forward(std::cos(info.heading_true_rad), std::sin(info.heading_true_rad),
                                0.0);
  for (const auto& l : scene.lights_of(r28, LightRole::kApproachCentreline)) {
    EXPECT_LT((l.position_scene_m.cast<double>() - info.threshold_scene_m).dot(forward), -29.0);
  }
  // Every light faces its end's approach (the beam axis against the landing direction).
  for (const auto& l : threshold) EXPECT_LT(l.beam_axis_scene.cast<double>().dot(forward), -0.9);
}

TEST(AirportScene, UnlightedAndClosedRunways) {
  auto ends = test::ksfo_runway_ends();
  for (auto& e : ends) {
    if (e.runway == "1L" || e.runway == "19R") e.closed = true;
    if (e.runway == "1R") e.lighted = false;
  }
  const Scene scene = build_airport_scene(ends, {});
  EXPECT_EQ(scene.find_end("1L"), -1);
  EXPECT_EQ(scene.find_end("19R"), -1);
  const int r1 = scene.find_end("1R");
  ASSERT_GE(r1, 0);
  for (const auto& l : scene.lights) EXPECT_NE(l.runway_end, r1);
  EXPECT_EQ(scene.notes.size(), 3u);
}

TEST(AirportScene, BadRecordsNameTheirField) {
  auto ends = test::ksfo_runway_ends();
  ends[3].threshold.lat_rad = std::nan("");
  try {
    build_airport_scene(ends, {});
    FAIL();
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("runway end KSFO 28L: field 'threshold.lat_rad'"),
              std::string::npos)
        << e.what();
  }
  ends = test::ksfo_runway_ends();
  ends[0].width_m = -3.0;
  EXPECT_THROW(build_airport_scene(ends, {}), std::invalid_argument);
  ends = test::ksfo_runway_ends();
  ends[0].runway = "H2";
  EXPECT_THROW(build_airport_scene(ends, {}), std::invalid_argument);
  EXPECT_THROW(build_airport_scene({}, {}), std::invalid_argument);
  AirportSceneOptions bad;
  bad.default_end.glide_path_rad = 12.0 * kDegToRad;
  EXPECT_THROW(build_airport_scene(test::ksfo_runway_ends(), bad), std::invalid_argument);
}

}  // namespace
}  // namespace fedsim::visual
