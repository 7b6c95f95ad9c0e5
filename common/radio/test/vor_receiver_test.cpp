// VOR receiver: radials against GeographicLib, CDI sense and scale, TO/FROM across the station,
// the cone of confusion, radio horizon and service volume, bad inputs.
#include "common/radio/vor_receiver.hpp"

#include "common/radio/radio_geometry.hpp"
#include "common/radio/test/station_fixtures.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <stdexcept>

namespace fedsim::radio::test {
namespace {

constexpr double kSlavedSfoDeg = 17.001;

/// The aircraft on the magnetic radial `radial_deg` of SFO at `distance_nm`.
AircraftPose on_radial(double radial_deg, double distance_nm, double altitude_ft) {
  const GeoPoint p = direct(sfo_vor_dme().position, radial_deg + kSlavedSfoDeg, distance_nm * kNm, 0);
  return pose_at(p, altitude_ft * kFt);
}

TEST(VorReceiver, RadialAndDistanceAgreeWithGeodesic) {
  const VorReceiver receiver;
  const Navaid sfo = sfo_vor_dme();
  for (double azimuth_deg = 0; azimuth_deg < 360; azimuth_deg += 30) {
    for (const double distance_nm : {3.0, 12.0, 35.0}) {
      const GeoPoint p = direct(sfo.position, azimuth_deg + 7.3, distance_nm * kNm, 0.0);
      const VorReading r = receiver.read(sfo, pose_at(p, 10000 * kFt), 0.0);
      ASSERT_TRUE(r.valid()) << to_string(r.status);
      const Inverse ref = inverse(sfo.position, p);
      EXPECT_NEAR(wrap_pi(r.radial_magnetic_rad - (ref.azimuth1_deg - kSlavedSfoDeg) * kDeg),
                  0.0, 1e-9);
      EXPECT_NEAR(r.ground_distance_m, ref.distance_m, 1e-6);
      EXPECT_NEAR(r.variation_rad, kSlavedSfoDeg * kDeg, 1e-12);
    }
  }
  // A known point: the 090 radial at 20 NM reads 090 and 20 NM.
  const VorReading east = receiver.read(sfo, on_radial(90, 20, 10000), 90 * kDeg);
  EXPECT_NEAR(east.radial_magnetic_rad, 90 * kDeg, 1e-9);
  EXPECT_NEAR(east.ground_distance_m, 20 * kNm, 1e-6);
  EXPECT_NEAR(east.course_true_rad, (90 + kSlavedSfoDeg) * kDeg, 1e-12);
}

TEST(VorReceiver, UsesMagneticVariationWhenSlavingUnknown) {
  Navaid sfo = sfo_vor_dme();
  sfo.slaved_variation_known = false;
  const GeoPoint p = direct(sfo.position, 100.0, 20 * kNm, 0.0);
  const VorReading r = VorReceiver().read(sfo, pose_at(p, 10000 * kFt), 0.0);
  EXPECT_NEAR(r.radial_magnetic_rad, (100.0 - 14.423) * kDeg, 1e-9);
  const VorReading slaved = VorReceiver().read(sfo_vor_dme(), pose_at(p, 10000 * kFt), 0.0);
  EXPECT_NEAR(slaved.radial_magnetic_rad, (100.0 - kSlavedSfoDeg) * kDeg, 1e-9);  // control
}

TEST(VorReceiver, CourseDeviationSenseAndScale) {
  const VorReceiver receiver;
  const Navaid sfo = sfo_vor_dme();
  // On radial 085, i.e. north of the 090 radial line east of the station.
  const AircraftPose north_of_line = on_radial(85, 20, 10000);
  // OBS 090 outbound (FROM): the course line is south, to the right of an aircraft heading 090.
  const VorReading from = receiver.read(sfo, north_of_line, 90 * kDeg);
  EXPECT_EQ(from.to_from, ToFrom::kFrom);
  EXPECT_NEAR(from.course_error_rad, 5 * kDeg, 1e-9);
  EXPECT_NEAR(from.course_deviation, 0.5, 1e-9);
  // OBS 270 inbound (TO): heading 270 the line is to the left.
  const VorReading to = receiver.read(sfo, north_of_line, 270 * kDeg);
  EXPECT_EQ(to.to_from, ToFrom::kTo);
  EXPECT_NEAR(to.course_deviation, -0.5, 1e-9);
  // Full scale at 10 deg, clamped beyond.
  EXPECT_NEAR(receiver.read(sfo, on_radial(80, 20, 10000), 90 * kDeg).course_deviation, 1.0, 1e-9);
  EXPECT_EQ(receiver.read(sfo, on_radial(60, 20, 10000), 90 * kDeg).course_deviation, 1.0);
  EXPECT_EQ(receiver.read(sfo, on_radial(120, 20, 10000), 90 * kDeg).course_deviation, -1.0);
  EXPECT_NEAR(receiver.read(sfo, on_radial(90, 20, 10000), 90 * kDeg).course_deviation, 0.0, 1e-9);
}

TEST(VorReceiver, ToFromFlipsAcrossTheStationWithTheNeedleSenseKept) {
  const VorReceiver receiver;
  const Navaid sfo = sfo_vor_dme();
  // Fly east (true course 090 + 17 = 107 T) along a line 2 NM north of the station.
  const double course_true_deg = 90 + kSlavedSfoDeg;
  const GeoPoint abeam = direct(sfo.position, course_true_deg - 90, 2 * kNm, 0);
  const GeoPoint before = direct(abeam, course_true_deg + 180, 15 * kNm, 0);
  const GeoPoint after = direct(abeam, course_true_deg, 15 * kNm, 0);
  const VorReading r_before = receiver.read(sfo, pose_at(before, 8000 * kFt), 90 * kDeg);
  const VorReading r_after = receiver.read(sfo, pose_at(after, 8000 * kFt), 90 * kDeg);
  ASSERT_TRUE(r_before.valid());
  ASSERT_TRUE(r_after.valid());
  EXPECT_EQ(r_before.to_from, ToFrom::kTo);
  EXPECT_EQ(r_after.to_from, ToFrom::kFrom);
  EXPECT_NE(r_before.to_from, r_after.to_from);
  // North of the course both times: fly right before and after (no reverse sensing).
  EXPECT_GT(r_before.course_deviation, 0.0);
  EXPECT_GT(r_after.course_deviation, 0.0);
  // Abeam: the OFF band about 90 deg from the course.
  EXPECT_EQ(receiver.read(sfo, on_radial(0, 20, 8000), 90 * kDeg).to_from, ToFrom::kOff);
  EXPECT_EQ(receiver.read(sfo, on_radial(3, 20, 8000), 90 * kDeg).to_from, ToFrom::kFrom);
  EXPECT_EQ(receiver.read(sfo, on_radial(357, 20, 8000), 90 * kDeg).to_from, ToFrom::kTo);
}

TEST(VorReceiver, ConeOfConfusionOverTheStation) {
  const VorReceiver receiver;
  const Navaid sfo = sfo_vor_dme();
  // 10,000 ft above: 1,000 m out is 72 deg up (inside the cone), 3,000 m out 45 deg.
  const GeoPoint close = direct(sfo.position, 200, 1000, 0);
  const GeoPoint clear = direct(sfo.position, 200, 3000, 0);
  const VorReading inside = receiver.read(sfo, pose_at(close, 10000 * kFt), 0);
  EXPECT_EQ(inside.status, SignalStatus::kConeOfConfusion);
  EXPECT_FALSE(inside.valid());
  EXPECT_EQ(inside.course_deviation, 0.0);
  EXPECT_EQ(inside.to_from, ToFrom::kOff);
  EXPECT_TRUE(receiver.read(sfo, pose_at(clear, 10000 * kFt), 0).valid());
  // A narrower cone setting admits the close point.
  VorReceiverSettings narrow_cone;
  narrow_cone.cone_of_confusion_elevation_rad = 80 * kDeg;
  EXPECT_TRUE(VorReceiver(narrow_cone).read(sfo, pose_at(close, 10000 * kFt), 0).valid());
}

TEST(VorReceiver, RadioHorizonAndServiceVolume) {
  const VorReceiver receiver;
  const Navaid sfo = sfo_vor_dme();
  // 35 NM: the 4/3-earth horizon of 13 ft and 300 ft antennas is 1.23 (sqrt 13 + sqrt 300) = 25.7 NM.
  EXPECT_EQ(receiver.read(sfo, on_radial(270, 35, 300), 0).status, SignalStatus::kBelowRadioHorizon);
  EXPECT_TRUE(receiver.read(sfo, on_radial(270, 35, 3000), 0).valid());
  EXPECT_EQ(receiver.read(sfo, on_radial(270, 60, 10000), 0).status,
            SignalStatus::kOutOfServiceVolume);
  EXPECT_TRUE(receiver.read(sfo, on_radial(270, 60, 20000), 0).valid());
  EXPECT_EQ(receiver.read(sfo, on_radial(270, 140, 30000), 0).status,
            SignalStatus::kOutOfServiceVolume);
}

TEST(VorReceiver, BadInputsAreFlaggedOrThrown) {
  const VorReceiver receiver;
  const Navaid sfo = sfo_vor_dme();
  AircraftPose pose = on_radial(90, 20, 10000);
  const double nan = std::numeric_limits<double>::quiet_NaN();
  EXPECT_EQ(receiver.read(sfo, pose, nan).status, SignalStatus::kInvalidInput);
  pose.altitude_msl_m = std::numeric_limits<double>::infinity();
  const VorReading bad = receiver.read(sfo, pose, 0);
  EXPECT_EQ(bad.status, SignalStatus::kInvalidInput);
  EXPECT_EQ(bad.radial_magnetic_rad, 0.0);
  EXPECT_EQ(bad.ident, "SFO");
  Navaid broken = sfo;
  broken.position.lat_rad = nan;
  EXPECT_THROW(receiver.read(broken, on_radial(90, 20, 10000), 0), std::invalid_argument);
  try {
    receiver.read(broken, on_radial(90, 20, 10000), 0);
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("'SFO' (id 93531): position.lat_rad"), std::string::npos)
        << e.what();
  }
  EXPECT_THROW(receiver.read(brijj_ndb(), on_radial(90, 20, 10000), 0), std::invalid_argument);
  VorReceiverSettings settings;
  settings.full_scale_rad = 0;
  EXPECT_THROW(VorReceiver{settings}, std::invalid_argument);
}

}  // namespace
}  // namespace fedsim::radio::test
