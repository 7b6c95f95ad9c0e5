// DME slant range and "no computed data" beyond range; ADF relative bearing and NDB range.
#include "nav/model/radio/adf_receiver.hpp"
#include "nav/model/radio/dme_receiver.hpp"
#include "nav/model/radio/radio_geometry.hpp"

#include "station_fixtures.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>

namespace fedsim::nav::test {
namespace {

TEST(DmeReceiver, SlantRangeOverheadIsTheHeightAboveTheAntenna) {
  const auto dme = dme_station(sfo_vor_dme());
  ASSERT_TRUE(dme.has_value());
  const GeoPoint at = dme->antenna;
  const DmeReading overhead = DmeReceiver().read(*dme, pose_at(at, 3048.0));
  ASSERT_TRUE(overhead.valid());
  EXPECT_NEAR(overhead.slant_range_m, 3048.0 - at.elevation_m, 1e-6);  // "minimum DME"
  EXPECT_NEAR(overhead.ground_distance_m, 0.0, 1e-6);
}

TEST(DmeReceiver, SlantRangeAgreesWithTheLocalSphere) {
  const auto dme = dme_station(sfo_vor_dme());
  const double radius_m = local_sphere_radius_m(dme->antenna.lat_rad);
  for (const double distance_nm : {2.0, 10.0, 30.0}) {
    const GeoPoint p = direct(dme->antenna, 123.0, distance_nm * kNm, 0);
    const double h = 9000 * kFt;
    const DmeReading r = DmeReceiver().read(*dme, pose_at(p, h));
    ASSERT_TRUE(r.valid());
    EXPECT_NEAR(r.ground_distance_m, distance_nm * kNm, 1e-6);
    const double expected =
        spherical_slant_range_m(distance_nm * kNm, dme->antenna.elevation_m, h, radius_m);
    EXPECT_NEAR(r.slant_range_m, expected, 2e-5 * expected) << distance_nm;
    EXPECT_GT(r.slant_range_m, r.ground_distance_m);
  }
}

TEST(DmeReceiver, NoComputedDataBeyondTheServiceVolume) {
  const auto dme = dme_station(sfo_vor_dme());  // BOTH -> H: 40 NM below 14,500 ft
  const GeoPoint p = direct(dme->antenna, 300.0, 45 * kNm, 0);
  EXPECT_EQ(DmeReceiver().read(*dme, pose_at(p, 10000 * kFt)).status,
            SignalStatus::kOutOfServiceVolume);
  const DmeReading high = DmeReceiver().read(*dme, pose_at(p, 25000 * kFt));
  EXPECT_TRUE(high.valid());  // 130 NM from 18,000 ft
  const DmeReading low = DmeReceiver().read(*dme, pose_at(direct(dme->antenna, 300, 30 * kNm, 0), 100));
  EXPECT_EQ(low.status, SignalStatus::kBelowRadioHorizon);
  EXPECT_EQ(low.slant_range_m, 0.0);
}

TEST(DmeReceiver, StationsThatHaveOne) {
  EXPECT_TRUE(dme_station(oak_vortac()).has_value());
  EXPECT_FALSE(dme_station(sau_vor_france()).has_value());  // VOR only
  EXPECT_FALSE(dme_station(brijj_ndb()).has_value());
  Navaid separate = sfo_vor_dme();
  separate.dme = point_deg(37.62, -122.375, 5.0);
  EXPECT_NEAR(dme_station(separate)->antenna.lat_rad, 37.62 * kDeg, 1e-12);
  const IlsApproach ils = ksfo_28r();
  const auto ils_dme = dme_station(ils);
  ASSERT_TRUE(ils_dme.has_value());
  EXPECT_EQ(ils_dme->service_class, VhfServiceClass::kTerminal);
  EXPECT_NEAR(ils_dme->antenna.lat_rad, ils.glide_slope.lat_rad, 1e-15);
  IlsApproach no_dme = ils;
  no_dme.has_dme = false;
  EXPECT_FALSE(dme_station(no_dme).has_value());
}

TEST(AdfReceiver, RelativeBearingIsBearingToStationMinusHeading) {
  const Navaid ndb = brijj_ndb();
  const GeoPoint p = direct(ndb.position, 200.0, 5 * kNm, 0);
  const Inverse to_ndb = inverse(p, ndb.position);  // at the aircraft: about 020 T
  for (const double heading_deg : {0.0, 350.0, 20.0, 50.0, 200.0}) {
    const AdfReading r = AdfReceiver().read(ndb, pose_at(p, 2000 * kFt, heading_deg));
    ASSERT_TRUE(r.valid());
    double expected_deg = std::fmod(to_ndb.azimuth1_deg - heading_deg + 720.0, 360.0);
    EXPECT_NEAR(r.relative_bearing_rad, expected_deg * kDeg, 1e-9) << heading_deg;
    EXPECT_GE(r.relative_bearing_rad, 0.0);
    EXPECT_LT(r.relative_bearing_rad, units::kTwoPi);
  }
  // Heading straight at the beacon: the needle on the nose; tail-on: 180 deg.
  EXPECT_NEAR(wrap_pi(
                  AdfReceiver().read(ndb, pose_at(p, 600, to_ndb.azimuth1_deg)).relative_bearing_rad),
              0.0, 1e-9);
  EXPECT_NEAR(AdfReceiver().read(ndb, pose_at(p, 600, to_ndb.azimuth1_deg + 180)).relative_bearing_rad,
              units::kPi, 1e-9);
}

TEST(AdfReceiver, RangeByPowerClassAndNoLineOfSightLimit) {
  const Navaid locator = kanan_ndb();  // compass locator: 15 NM
  EXPECT_EQ(AdfReceiver().read(locator, pose_at(direct(locator.position, 90, 16 * kNm, 0), 3000)).status,
            SignalStatus::kOutOfServiceVolume);
  // 14 NM at 50 ft: a VHF station there would be below the radio horizon (1.23 (sqrt 5 + sqrt 50)
  // = 11.5 NM), the ground wave of an NDB is not.
  const GeoPoint low = direct(locator.position, 90, 14 * kNm, 0);
  EXPECT_FALSE(within_radio_line_of_sight(locator.position.elevation_m, 50 * kFt, 14 * kNm));
  EXPECT_TRUE(AdfReceiver().read(locator, pose_at(low, 50 * kFt)).valid());
  // MH class: 25 NM.
  const Navaid mh = reiga_ndb();
  EXPECT_TRUE(AdfReceiver().read(mh, pose_at(direct(mh.position, 10, 24 * kNm, 0), 3000)).valid());
  EXPECT_FALSE(AdfReceiver().read(mh, pose_at(direct(mh.position, 10, 26 * kNm, 0), 3000)).valid());
}

TEST(AdfReceiver, BadInputs) {
  AircraftPose pose = pose_at(brijj_ndb().position, 1000);
  pose.heading_true_rad = std::nan("");
  EXPECT_EQ(AdfReceiver().read(brijj_ndb(), pose).status, SignalStatus::kInvalidInput);
  EXPECT_THROW(AdfReceiver().read(sfo_vor_dme(), pose_at(brijj_ndb().position, 1000)),
               std::invalid_argument);
}

}  // namespace
}  // namespace fedsim::nav::test
