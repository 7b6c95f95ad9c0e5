// The ADF: relative bearing and NDB range (the receiver), and the tuner over an in-memory station
// source (which beacon is received on a frequency, outages, receiver failures).
#include "common/radio/in_memory_station_source.hpp"
#include "common/radio/radio_geometry.hpp"
#include "nav/model/radio/adf_radio.hpp"
#include "nav/model/radio/adf_receiver.hpp"

#include "common/radio/test/station_fixtures.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>

namespace fedsim::nav::test {

using namespace fedsim::radio::test;  // the station records and poses (common/radio/test)
namespace {

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
            radio::SignalStatus::kOutOfServiceVolume);
  // 14 NM at 50 ft: a VHF station there would be below the radio horizon (1.23 (sqrt 5 + sqrt 50)
  // = 11.5 NM), the ground wave of an NDB is not.
  const GeoPoint low = direct(locator.position, 90, 14 * kNm, 0);
  EXPECT_FALSE(radio::within_radio_line_of_sight(locator.position.elevation_m, 50 * kFt, 14 * kNm));
  EXPECT_TRUE(AdfReceiver().read(locator, pose_at(low, 50 * kFt)).valid());
  // MH class: 25 NM.
  const Navaid mh = reiga_ndb();
  EXPECT_TRUE(AdfReceiver().read(mh, pose_at(direct(mh.position, 10, 24 * kNm, 0), 3000)).valid());
  EXPECT_FALSE(AdfReceiver().read(mh, pose_at(direct(mh.position, 10, 26 * kNm, 0), 3000)).valid());
}

TEST(AdfReceiver, BadInputs) {
  radio::AircraftPose pose = pose_at(brijj_ndb().position, 1000);
  pose.heading_true_rad = std::nan("");
  EXPECT_EQ(AdfReceiver().read(brijj_ndb(), pose).status, radio::SignalStatus::kInvalidInput);
  EXPECT_THROW(AdfReceiver().read(sfo_vor_dme(), pose_at(brijj_ndb().position, 1000)),
               std::invalid_argument);
}

class AdfRadioTest : public ::testing::Test {
 protected:
  AdfRadioTest() {
    source_.add(brijj_ndb());
    source_.add(kanan_ndb());
  }

  radio::InMemoryStationSource source_;
  radio::StationOutages outages_;
};

TEST_F(AdfRadioTest, TunerFailuresAndBand) {
  AdfRadio adf(source_, outages_);
  const radio::AircraftPose pose = near_bay_area();
  const AdfReading r = adf.receive(379, pose);
  ASSERT_TRUE(r.valid()) << to_string(r.status);
  EXPECT_EQ(r.ident, "SF");
  EXPECT_EQ(adf.receive(335, pose).status, radio::SignalStatus::kOutOfServiceVolume);  // CC: 15 NM locator
  EXPECT_EQ(adf.receive(100, pose).status, radio::SignalStatus::kNotTuned);
  EXPECT_EQ(adf.receive(400, pose).status, radio::SignalStatus::kNoStation);
  outages_.set_off_air("SF");
  EXPECT_EQ(adf.receive(379, pose).status, radio::SignalStatus::kStationOffAir);
  outages_.clear();
  adf.set_failed(true);
  EXPECT_EQ(adf.receive(379, pose).status, radio::SignalStatus::kReceiverFailed);
}

}  // namespace
}  // namespace fedsim::nav::test
