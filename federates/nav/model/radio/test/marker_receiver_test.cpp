// Marker beacons: passage order and lit lengths on a 3 deg approach against the ICAO coverage
// figures (Annex 10 Vol I 3.1.7.3.2: 600 +- 200 m, 300 +- 100 m, 150 +- 50 m), the codes, an
// offset path that passes none, outages and failure.
#include "nav/model/radio/marker_receiver.hpp"

#include "common/radio/test/station_fixtures.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

namespace fedsim::nav::test {

using namespace fedsim::radio::test;  // the station records and poses (common/radio/test)
namespace {

struct Passage {
  MarkerBeacon beacon;
  double length_m;
};

// Flies the glide path (height TCH + d tan theta over the threshold) along the extended
// centreline from 8 NM to the threshold, `left_m` to the left, and lists the beacons heard.
std::vector<Passage> fly_approach(const IlsApproach& ils, const radio::StationOutages& outages,
                                  double left_m = 0.0) {
  const MarkerReceiver receiver;
  const Inverse line = inverse(ils.threshold, ils.localizer);
  const double azimuth_deg = line.azimuth1_deg + 180.0;  // from the threshold out the approach
  std::vector<Passage> passages;
  constexpr double kStepM = 2.0;
  bool last_valid = false;
  for (double d = 8 * kNm; d >= 0.0; d -= kStepM) {
    double forward_deg = 0.0;
    GeoPoint p = direct(ils.threshold, azimuth_deg, d, 0.0, &forward_deg);
    if (left_m != 0.0) p = direct(p, forward_deg + 90.0, left_m, 0.0);  // facing inbound: left
    const double h = ils.threshold.elevation_m + ils.threshold_crossing_height_m +
                     d * std::tan(ils.glide_path_angle_rad);
    const MarkerReading r = receiver.read({&ils, 1}, pose_at(p, h), outages);
    if (!r.valid()) {
      last_valid = false;
      continue;
    }
    if (passages.empty() || passages.back().beacon != r.beacon || !last_valid) {
      passages.push_back({r.beacon, 0.0});
    }
    passages.back().length_m += kStepM;
    last_valid = true;
  }
  return passages;
}

TEST(MarkerBeacons, PassageOrderAndLengthOnA3DegreeApproach) {
  const std::vector<Passage> passages = fly_approach(ksfo_28r(), radio::StationOutages{});
  ASSERT_EQ(passages.size(), 3u);
  EXPECT_EQ(passages[0].beacon, MarkerBeacon::kOuter);
  EXPECT_EQ(passages[1].beacon, MarkerBeacon::kMiddle);
  EXPECT_EQ(passages[2].beacon, MarkerBeacon::kInner);
  EXPECT_NEAR(passages[0].length_m, 600, 200);
  EXPECT_NEAR(passages[1].length_m, 300, 100);
  EXPECT_NEAR(passages[2].length_m, 150, 50);
}

TEST(MarkerBeacons, OffsetPathHearsNoneAndOutagesSilenceThem) {
  EXPECT_TRUE(fly_approach(ksfo_28r(), radio::StationOutages{}, 1000.0).empty());
  radio::StationOutages markers_off;
  markers_off.set_off_air("ISFO", radio::StationComponent::kMarkers);
  EXPECT_TRUE(fly_approach(ksfo_28r(), markers_off).empty());
  radio::StationOutages glide_slope_off;  // another component: markers still heard
  glide_slope_off.set_off_air("ISFO", radio::StationComponent::kGlideSlope);
  EXPECT_EQ(fly_approach(ksfo_28r(), glide_slope_off).size(), 3u);
}

TEST(MarkerBeacons, CodesAndFailure) {
  EXPECT_EQ(marker_code(MarkerBeacon::kOuter).lamp, MarkerLamp::kBlue);
  EXPECT_EQ(marker_code(MarkerBeacon::kOuter).tone_hz, 400.0);
  EXPECT_EQ(marker_code(MarkerBeacon::kMiddle).lamp, MarkerLamp::kAmber);
  EXPECT_EQ(marker_code(MarkerBeacon::kMiddle).tone_hz, 1300.0);
  EXPECT_EQ(marker_code(MarkerBeacon::kInner).lamp, MarkerLamp::kWhite);
  EXPECT_EQ(marker_code(MarkerBeacon::kInner).tone_hz, 3000.0);
  EXPECT_EQ(marker_code(MarkerBeacon::kNone).lamp, MarkerLamp::kOff);

  const IlsApproach ils = ksfo_28r();
  // Over the outer marker on the glide path.
  const Inverse line = inverse(ils.threshold, ils.localizer);
  const GeoPoint om = direct(ils.threshold, line.azimuth1_deg + 180, *ils.outer_marker_distance_m, 0);
  const radio::AircraftPose over_om = pose_at(om, 450.0);
  MarkerReceiver receiver;
  const MarkerReading heard = receiver.read({&ils, 1}, over_om, radio::StationOutages{});
  ASSERT_TRUE(heard.valid());
  EXPECT_EQ(heard.beacon, MarkerBeacon::kOuter);
  EXPECT_EQ(heard.ident, "ISFO");
  EXPECT_EQ(heard.code.lamp, MarkerLamp::kBlue);
  receiver.set_failed(true);
  const MarkerReading failed = receiver.read({&ils, 1}, over_om, radio::StationOutages{});
  EXPECT_EQ(failed.status, radio::SignalStatus::kReceiverFailed);
  EXPECT_EQ(failed.beacon, MarkerBeacon::kNone);
}

}  // namespace
}  // namespace fedsim::nav::test
