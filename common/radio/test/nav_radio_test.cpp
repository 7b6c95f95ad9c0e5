// The NAV tuner over an in-memory station source: which station is received on a
// frequency, co-channel selection, the ILS path, outages and receiver failures.
#include "common/radio/in_memory_station_source.hpp"
#include "common/radio/nav_radio.hpp"
#include "common/radio/radio_geometry.hpp"

#include "common/radio/test/station_fixtures.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <stdexcept>

namespace fedsim::radio::test {
namespace {

class NavRadioTest : public ::testing::Test {
 protected:
  NavRadioTest() {
    source_.add(sfo_vor_dme());
    source_.add(oak_vortac());
    source_.add(sau_vor_france());
    source_.add(sjc_vor_dme());
    source_.add(brijj_ndb());
    source_.add(kanan_ndb());
    source_.add(ksfo_28r());
  }

  InMemoryStationSource source_;
  StationOutages outages_;
};

TEST_F(NavRadioTest, ReceivesTheVorAndItsDme) {
  const NavRadio radio(source_, outages_);
  const NavReading r = radio.receive({115800, 300 * kDeg}, near_bay_area());
  ASSERT_TRUE(r.valid()) << to_string(r.status);
  EXPECT_EQ(r.signal, NavSignal::kVor);
  EXPECT_EQ(r.ident(), "SFO");
  EXPECT_NEAR(r.vor.radial_magnetic_rad, (135 - 17.001) * kDeg, 1e-9);
  EXPECT_EQ(r.course_deviation(), r.vor.course_deviation);
  EXPECT_NEAR(r.course_true_rad(), (300 + 17.001) * kDeg, 1e-12);
  ASSERT_TRUE(r.dme.valid());
  EXPECT_EQ(r.dme.ident, "SFO");
  EXPECT_GT(r.dme.slant_range_m, 10 * kNm);
  EXPECT_EQ(r.glide_slope.status, SignalStatus::kNoStation);
  EXPECT_EQ(r.approach, nullptr);
}

TEST_F(NavRadioTest, CoChannelStationsTheNearestReceivedWins) {
  const NavRadio radio(source_, outages_);
  // OAK (California) and SAU (France) share 116.80 MHz.
  const NavReading bay = radio.receive({116800, 0}, near_bay_area());
  ASSERT_TRUE(bay.valid());
  EXPECT_EQ(bay.ident(), "OAK");
  const AircraftPose bordeaux = pose_at(point_deg(44.83, -0.69, 0), 10000 * kFt);
  const NavReading france = radio.receive({116800, 0}, bordeaux);
  ASSERT_TRUE(france.valid());
  EXPECT_EQ(france.ident(), "SAU");
  EXPECT_FALSE(france.dme.valid());  // SAU is a VOR without DME; OAK is out of range there
  // Both in range: the nearer. A second station on 115.80, 50 NM west of SFO (H class).
  Navaid far = sfo_vor_dme();
  far.ident = "TST";
  far.id = 1;
  far.position = direct(sfo_vor_dme().position, 270, 50 * kNm, 0);
  source_.add(far);
  const AircraftPose high_between = pose_at(direct(sfo_vor_dme().position, 270, 20 * kNm, 0),
                                            25000 * kFt);
  EXPECT_EQ(radio.receive({115800, 0}, high_between).ident(), "SFO");
  const AircraftPose nearer_tst = pose_at(direct(sfo_vor_dme().position, 270, 30 * kNm, 0),
                                          25000 * kFt);
  EXPECT_EQ(radio.receive({115800, 0}, nearer_tst).ident(), "TST");
  // SFO off the air: TST is received instead, valid.
  outages_.set_off_air("SFO");
  const NavReading fallback = radio.receive({115800, 0}, high_between);
  EXPECT_TRUE(fallback.valid());
  EXPECT_EQ(fallback.ident(), "TST");
}

TEST_F(NavRadioTest, OffAirStationIsFlaggedNotRead) {
  const NavRadio radio(source_, outages_);
  outages_.set_off_air("OAK");
  const NavReading r = radio.receive({116800, 0}, near_bay_area());
  EXPECT_FALSE(r.valid());
  EXPECT_EQ(r.status, SignalStatus::kStationOffAir);  // the nearest, OAK; SAU is out of range
  EXPECT_EQ(r.course_deviation(), 0.0);
  EXPECT_FALSE(r.dme.valid());
  outages_.set_off_air("OAK", StationComponent::kAll, false);
  EXPECT_TRUE(radio.receive({116800, 0}, near_bay_area()).valid());  // back on the air
  // Only the DME of SFO off the air: the VOR is still received.
  outages_.set_off_air("SFO", StationComponent::kDme);
  const NavReading vor_only = radio.receive({115800, 0}, near_bay_area());
  EXPECT_TRUE(vor_only.valid());
  EXPECT_EQ(vor_only.dme.status, SignalStatus::kStationOffAir);
}

TEST_F(NavRadioTest, IlsLocalizerGlideSlopeAndDme) {
  const NavRadio radio(source_, outages_);
  const IlsApproach ils = ksfo_28r();
  const GeoPoint on_centreline = from_localizer(ils, 8 * kNm, 0.0);
  const AircraftPose pose =
      at_elevation_from_glide_slope(ils, on_centreline, ils.glide_path_angle_rad);
  const NavReading r = radio.receive({109550, 0.0}, pose);
  ASSERT_TRUE(r.valid());
  EXPECT_EQ(r.signal, NavSignal::kLocalizer);
  EXPECT_EQ(r.ident(), "ISFO");
  EXPECT_NEAR(r.course_deviation(), 0.0, 1e-3);
  EXPECT_NEAR(wrap_pi(r.course_true_rad() - ils.course_true_rad), 0.0, 1e-12);
  ASSERT_TRUE(r.glide_slope.valid());
  EXPECT_NEAR(r.glide_slope.deviation, 0.0, 1e-6);
  ASSERT_TRUE(r.dme.valid());
  EXPECT_EQ(r.dme.ident, "ISFO");
  ASSERT_NE(r.approach, nullptr);
  EXPECT_EQ(r.approach->runway, "28R");
  outages_.set_off_air("ISFO", StationComponent::kGlideSlope);
  const NavReading no_gs = radio.receive({109550, 0.0}, pose);
  EXPECT_TRUE(no_gs.valid());
  EXPECT_EQ(no_gs.glide_slope.status, SignalStatus::kStationOffAir);
  EXPECT_EQ(no_gs.glide_slope.deviation, 0.0);
}

TEST_F(NavRadioTest, FailedReceiverUntunedAndBadInputs) {
  NavRadio radio(source_, outages_);
  radio.set_failed(true);
  const NavReading failed = radio.receive({115800, 0}, near_bay_area());
  EXPECT_EQ(failed.status, SignalStatus::kReceiverFailed);
  EXPECT_EQ(failed.dme.status, SignalStatus::kReceiverFailed);
  EXPECT_FALSE(failed.valid());
  EXPECT_EQ(failed.course_deviation(), 0.0);
  radio.set_failed(false);
  EXPECT_TRUE(radio.receive({115800, 0}, near_bay_area()).valid());  // control
  EXPECT_EQ(radio.receive({0, 0}, near_bay_area()).status, SignalStatus::kNotTuned);
  EXPECT_EQ(radio.receive({121500, 0}, near_bay_area()).status, SignalStatus::kNotTuned);
  EXPECT_EQ(radio.receive({113000, 0}, near_bay_area()).status, SignalStatus::kNoStation);
  EXPECT_EQ(radio.receive({115800, std::numeric_limits<double>::quiet_NaN()}, near_bay_area()).status,
            SignalStatus::kInvalidInput);
  AircraftPose bad = near_bay_area();
  bad.true_airspeed_mps = -1;
  EXPECT_EQ(radio.receive({115800, 0}, bad).status, SignalStatus::kInvalidInput);
}

TEST(InMemoryStationSource, RejectsBadRecords) {
  InMemoryStationSource source;
  Navaid bad = sfo_vor_dme();
  bad.magnetic_variation_rad = std::numeric_limits<double>::infinity();
  EXPECT_THROW(source.add(bad), std::invalid_argument);
  IlsApproach bad_ils = ksfo_28r();
  bad_ils.localizer.elevation_m = 20000;  // feet taken for metres
  EXPECT_THROW(source.add(bad_ils), std::invalid_argument);
  EXPECT_TRUE(source.stations_on(115800).navaids.empty());
  StationOutages outages;
  EXPECT_THROW(outages.set_off_air(""), std::invalid_argument);
}

}  // namespace
}  // namespace fedsim::radio::test
