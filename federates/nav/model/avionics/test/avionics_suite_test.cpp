// The navigation executive: radios, markers, GPS, INS and flight director stepped together on a
// true flight, the failures shown as invalid readings, the database-backed station source.
#include "common/radio/in_memory_station_source.hpp"
#include "common/radio/test/station_fixtures.hpp"
#include "nav/model/avionics/avionics_suite.hpp"
#include "nav/model/avionics/database_station_source.hpp"

#include "common/units/units.hpp"

#include <gtest/gtest.h>

namespace fedsim::nav {
namespace {

using units::kDegToRad;

/// Straight and level flight at `speed_mps` on true heading `heading_deg` through `start`,
/// as the flat-earth flight model would report it (rates relative to NED, no specific force
/// but the one that holds it up).
AvionicsTruth level_flight(const GeoPoint& start, double altitude_m, double heading_deg,
                           double speed_mps, double t_s) {
  const GeoPoint here = radio::test::direct(start, heading_deg, speed_mps * t_s, start.elevation_m);
  AvionicsTruth t;
  t.lat_rad = here.lat_rad;
  t.lon_rad = here.lon_rad;
  t.altitude_msl_m = altitude_m;
  const double psi = heading_deg * kDegToRad;
  t.velocity_ned_mps = {speed_mps * std::cos(psi), speed_mps * std::sin(psi), 0.0};
  t.euler = {0.0, 0.0, psi};
  t.q_ned_from_body = quaternion_from_euler(t.euler);
  t.true_airspeed_mps = speed_mps;
  t.specific_force_body_mps2 = {0.0, 0.0, -units::kStandardGravityMps2};
  return t;
}

class AvionicsSuiteTest : public ::testing::Test {
 protected:
  AvionicsSuiteTest() {
    stations_.add(radio::test::sfo_vor_dme());
    stations_.add(radio::test::ksfo_28r());
    approaches_.push_back(radio::test::ksfo_28r());
  }
  radio::InMemoryStationSource stations_;
  std::vector<IlsApproach> approaches_;
};

TEST_F(AvionicsSuiteTest, FlyingAcrossTheVorTurnsToIntoFrom) {
  AvionicsSuite suite(stations_, approaches_, {});
  suite.radios().nav[0] = {115800, 90.0 * kDegToRad};
  // From 10 NM west of SFO eastbound at 3000 ft and 60 m/s, across the station.
  const GeoPoint start = radio::test::direct(radio::test::sfo_vor_dme().position, 270.0, 10.0 * units::kNmToM, 0.0);
  const double altitude = 3000.0 * units::kFtToM;
  suite.align(level_flight(start, altitude, 90.0, 60.0, 0.0));
  std::vector<radio::ToFrom> flags;
  for (double t = 0.0; t <= 600.0; t += 0.5) {
    const auto& r = suite.step(level_flight(start, altitude, 90.0, 60.0, t), 0.5, t);
    if (r.nav[0].signal == radio::NavSignal::kVor && r.nav[0].valid()) flags.push_back(r.nav[0].vor.to_from);
  }
  ASSERT_GT(flags.size(), 1000u);
  EXPECT_EQ(flags.front(), radio::ToFrom::kTo);
  EXPECT_EQ(flags.back(), radio::ToFrom::kFrom);  // negative control: the same flag before and after would fail
  const auto first_from = std::find(flags.begin(), flags.end(), radio::ToFrom::kFrom);
  EXPECT_TRUE(std::all_of(first_from, flags.end(), [](radio::ToFrom f) { return f == radio::ToFrom::kFrom; }));
}

TEST_F(AvionicsSuiteTest, FailuresShowAsInvalidReadingsNeverAsValues) {
  AvionicsSuite suite(stations_, approaches_, {});
  suite.radios().nav[0] = {115800, 0.0};
  suite.radios().nav[1] = {115800, 0.0};
  const GeoPoint start = radio::test::direct(radio::test::sfo_vor_dme().position, 270.0, 8.0 * units::kNmToM, 0.0);
  const auto at = [&](double t) { return level_flight(start, 900.0, 90.0, 60.0, t); };
  suite.align(at(0.0));
  auto r = suite.step(at(0.02), 0.02, 0.02);
  ASSERT_TRUE(r.nav[0].valid());
  ASSERT_TRUE(r.nav[1].valid());
  ASSERT_TRUE(r.gps.valid);
  ASSERT_TRUE(r.ins_valid);

  suite.failures().nav[0] = true;
  suite.failures().gps_denied = true;
  suite.failures().ins = true;
  r = suite.step(at(0.04), 0.02, 0.04);
  EXPECT_EQ(r.nav[0].status, radio::SignalStatus::kReceiverFailed);
  EXPECT_EQ(r.nav[0].course_deviation(), 0.0);
  EXPECT_TRUE(r.nav[1].valid());  // the other receiver is unaffected
  EXPECT_FALSE(r.gps.valid);
  EXPECT_TRUE(std::isnan(r.gps.position.lat_rad));
  EXPECT_FALSE(r.ins_valid);
  EXPECT_FALSE(r.fd.roll_valid && r.fd_lateral == LateralMode::kNavTrack);

  suite.failures() = {};
  suite.failures().stations.set_off_air("SFO");
  r = suite.step(at(0.06), 0.02, 0.06);
  EXPECT_EQ(r.nav[1].status, radio::SignalStatus::kStationOffAir);
  EXPECT_TRUE(r.gps.valid);
  EXPECT_TRUE(r.ins_valid);  // realigned after the restore
  EXPECT_LT(r.ins_errors.horizontal_position_m, 0.01);
}

TEST_F(AvionicsSuiteTest, InsFollowsAFlatEarthFlightAndItsErrorsGrowWithAPoorImu) {
  const GeoPoint start = radio::test::point_deg(37.0, -122.0, 0.0);
  auto run = [&](ImuErrors errors) {
    AvionicsConfig config;
    config.ins.imu_errors = errors;
    AvionicsSuite suite(stations_, approaches_, config);
    // Northbound along a meridian (a geodesic and a line of constant heading at once), low, so
    // that the truth's surface distance and the INS's integrated speed agree (h/R ~ 2e-5).
    suite.align(level_flight(start, 100.0, 0.0, 70.0, 0.0));
    double worst = 0.0;
    for (double t = 0.05; t <= 600.0; t += 0.05) {
      const auto& r = suite.step(level_flight(start, 100.0, 0.0, 70.0, t), 0.05, t);
      worst = std::max(worst, r.ins_errors.horizontal_position_m);
    }
    return worst;
  };
  // A perfect IMU built from the flat-earth kinematics on the rotating earth: the INS follows
  // 42 km of straight flight within a few metres (the truth's position is advanced along the
  // ellipsoid surface, the INS's at 100 m: 42 km x 100 m / 6371 km = 0.7 m).
  const double perfect = run(ImuErrors::none());
  EXPECT_LT(perfect, 5.0);
  ImuErrors biased = ImuErrors::none();
  biased.accel_bias_body_mps2 = {1e-3 * units::kStandardGravityMps2, 0.0, 0.0};  // 1 mg
  EXPECT_GT(run(biased), perfect + 100.0);
}

TEST_F(AvionicsSuiteTest, FlightDirectorTracksTheLocalizerAndGlideSlopeWhenTheyAreValid) {
  AvionicsSuite suite(stations_, approaches_, {});
  const IlsApproach ils = radio::test::ksfo_28r();
  suite.radios().nav[0] = {ils.frequency_khz, 0.0};
  // 6 NM out on the extended centreline, right of it by 300 m, on the glide path.
  const double back = ils.course_true_rad * units::kRadToDeg + 180.0;
  GeoPoint p = radio::test::direct(ils.threshold, back, 6.0 * units::kNmToM, 0.0);
  p = radio::test::direct(p, back - 90.0, 300.0, 0.0);  // the right of the inbound course
  const double height = 6.0 * units::kNmToM * std::tan(ils.glide_path_angle_rad) +
                        ils.threshold_crossing_height_m + ils.threshold.elevation_m;
  const auto truth = level_flight(p, height, ils.course_true_rad * units::kRadToDeg, 70.0, 0.0);
  suite.align(truth);
  const auto& r = suite.step(truth, 0.02, 0.02);
  ASSERT_TRUE(r.nav[0].valid()) << to_string(r.nav[0].status);
  EXPECT_EQ(r.nav[0].signal, radio::NavSignal::kLocalizer);
  EXPECT_EQ(r.fd_lateral, LateralMode::kNavTrack);
  EXPECT_EQ(r.fd_vertical, VerticalMode::kGlideSlopeTrack);
  EXPECT_TRUE(r.fd.roll_valid);
  // Right of a course flown inbound: fly left, a left bank (negative roll).
  EXPECT_LT(r.nav[0].course_deviation(), 0.0);
  EXPECT_LT(r.fd.roll_command_rad, 0.0);
  // Negative control: left of the centreline the command reverses.
  GeoPoint left = radio::test::direct(radio::test::direct(ils.threshold, back, 6.0 * units::kNmToM, 0.0),
                               back + 90.0, 300.0, 0.0);
  const auto& l = suite.step(level_flight(left, height, ils.course_true_rad * units::kRadToDeg, 70.0, 0.0), 0.02, 0.04);
  EXPECT_GT(l.fd.roll_command_rad, 0.0);
}

TEST(DatabaseStationSource, FindsTheShippedStationsOnceAndKeepsThem) {
  const NavDatabase db = NavDatabase::open(default_database_path());
  DatabaseStationSource source(db);
  EXPECT_GE(source.all_approaches().size(), 12u);
  const auto ils = source.stations_on(111700);  // KSFO 28R I-GWQ (data/nav/ils.csv)
  ASSERT_FALSE(ils.approaches.empty());
  EXPECT_TRUE(std::any_of(ils.approaches.begin(), ils.approaches.end(),
                          [](const IlsApproach& a) { return a.airport == "KSFO" && a.runway == "28R"; }));
  const auto vor = source.stations_on(115800);
  EXPECT_TRUE(std::any_of(vor.navaids.begin(), vor.navaids.end(),
                          [](const Navaid& n) { return n.ident == "SFO"; }));
  const std::size_t cached = source.cached_frequencies();
  const auto again = source.stations_on(115800);
  EXPECT_EQ(again.navaids.data(), vor.navaids.data());  // the same storage: no new query
  EXPECT_EQ(source.cached_frequencies(), cached);
}

}  // namespace
}  // namespace fedsim::nav
