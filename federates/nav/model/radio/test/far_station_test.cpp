// Stations beyond any reception are culled by a cheap distance bound (radio_geometry.hpp) and
// reported out of their service volume; the bound never exceeds the geodesic distance, so no
// station that could be heard is culled.
#include "common/radio/in_memory_station_source.hpp"
#include "common/radio/nav_radio.hpp"
#include "common/radio/radio_geometry.hpp"
#include "common/radio/test/station_fixtures.hpp"
#include "nav/model/radio/adf_radio.hpp"

#include <gtest/gtest.h>

#include <random>

namespace fedsim::nav {
namespace {

TEST(FarStations, TheLowerBoundNeverExceedsTheGeodesicDistance) {
  std::mt19937_64 random(3);
  std::uniform_real_distribution<double> lat(-89.0, 89.0), lon(-180.0, 180.0);
  double tightest = 0.0;
  for (int i = 0; i < 20000; ++i) {
    const GeoPoint a = radio::test::point_deg(lat(random), lon(random), 0.0);
    const GeoPoint b = radio::test::point_deg(lat(random), lon(random), 0.0);
    const double exact = radio::ground_distance_m(a, b.lat_rad, b.lon_rad);
    const double bound = radio::ground_distance_lower_bound_m(a, b.lat_rad, b.lon_rad);
    ASSERT_LE(bound, exact) << i;
    tightest = std::max(tightest, bound / exact);
  }
  EXPECT_GT(tightest, 0.98);  // and it is a useful bound, not zero
}

TEST(FarStations, AFarStationIsFlaggedAndANearOneOnTheFrequencyIsStillReceived) {
  radio::InMemoryStationSource far_only, both;
  Navaid far = radio::test::sfo_vor_dme();
  far.id = 1;
  far.ident = "FAR";
  far.position = radio::test::direct(radio::test::sfo_vor_dme().position, 90.0, 500.0 * units::kNmToM, 0.0);
  far_only.add(far);
  both.add(far);
  both.add(radio::test::sfo_vor_dme());
  const radio::StationOutages outages;
  const radio::AircraftPose pose =
      radio::test::pose_at(radio::test::direct(radio::test::sfo_vor_dme().position, 270.0, 10.0 * units::kNmToM, 0.0),
                    3000.0 * units::kFtToM, 90.0);
  const radio::NavReading alone = radio::NavRadio(far_only, outages).receive({115800, 0.0}, pose);
  EXPECT_EQ(alone.status, radio::SignalStatus::kOutOfServiceVolume);
  EXPECT_EQ(alone.vor.ident, "FAR");
  const radio::NavReading near = radio::NavRadio(both, outages).receive({115800, 0.0}, pose);
  EXPECT_TRUE(near.valid());
  EXPECT_EQ(near.vor.ident, "SFO");
}

}  // namespace
}  // namespace fedsim::nav
