// DME slant range and "no computed data" beyond range.
#include "common/radio/dme_receiver.hpp"
#include "common/radio/radio_geometry.hpp"

#include "common/radio/test/station_fixtures.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>

namespace fedsim::radio::test {
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

}  // namespace
}  // namespace fedsim::radio::test
