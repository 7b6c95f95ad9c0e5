// ILS localizer on the KSFO 28R record built from the OurAirports runway ends: zero on the
// centreline and over the threshold, full scale at half the course width, sense, width rule,
// coverage and behind the antenna.
#include "common/radio/localizer_receiver.hpp"

#include "common/radio/approach_geometry.hpp"
#include "common/radio/test/station_fixtures.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <optional>
#include <stdexcept>

namespace fedsim::radio::test {
namespace {

double on_path_altitude_m(const IlsApproach& ils, double from_localizer_m) {
  const double from_threshold_m = from_localizer_m - inverse(ils.localizer, ils.threshold).distance_m;
  return ils.threshold.elevation_m + ils.threshold_crossing_height_m +
         std::max(0.0, from_threshold_m) * std::tan(ils.glide_path_angle_rad);
}

LocalizerReading read_at(const IlsApproach& ils, double distance_m, double offset_deg,
                         std::optional<double> altitude_m = std::nullopt) {
  const GeoPoint p = from_localizer(ils, distance_m, offset_deg);
  return LocalizerReceiver().read(
      ils, pose_at(p, altitude_m.value_or(on_path_altitude_m(ils, distance_m)), ils.course_true_rad / kDeg));
}

// Half the sector by the rule, computed here from the runway geometry: atan(350 ft / D).
double rule_half_width_rad(const IlsApproach& ils) {
  return std::atan(350 * kFt / inverse(ils.localizer, ils.threshold).distance_m);
}

TEST(Localizer, ZeroOnTheCentrelineAndOverTheThreshold) {
  const IlsApproach ils = ksfo_28r();
  for (const double nm : {1.0, 3.0, 6.0, 10.0, 17.0}) {
    const LocalizerReading r = read_at(ils, nm * kNm, 0.0);
    ASSERT_TRUE(r.valid()) << nm << " " << to_string(r.status);
    EXPECT_NEAR(r.deviation, 0.0, 1e-6) << nm;
    EXPECT_NEAR(r.ddm, 0.0, 1e-6) << nm;
  }
  // The course line passes over the runway threshold (the record puts the antenna on the
  // extended centreline): less than 1 m off, 0.01 of full scale.
  const LocalizerReading over_threshold =
      LocalizerReceiver().read(ils, pose_at(ils.threshold, ils.threshold.elevation_m + 15));
  ASSERT_TRUE(over_threshold.valid());
  EXPECT_LT(std::abs(over_threshold.deviation), 0.01);
}

TEST(Localizer, FullScaleAtHalfTheCourseWidthWithFlyRightOnTheLeft) {
  const IlsApproach ils = ksfo_28r();
  const double half_deg = rule_half_width_rad(ils) / kDeg;
  EXPECT_NEAR(half_deg, 1.595, 0.01);  // 700 ft over 12,570 ft: a 3.19 deg course
  for (const double nm : {2.0, 8.0}) {
    const LocalizerReading left = read_at(ils, nm * kNm, +half_deg);
    const LocalizerReading right = read_at(ils, nm * kNm, -half_deg);
    EXPECT_NEAR(left.deviation, 1.0, 1e-6);
    EXPECT_NEAR(left.ddm, 0.155, 1e-6);
    EXPECT_NEAR(right.deviation, -1.0, 1e-6);
    EXPECT_NEAR(read_at(ils, nm * kNm, 0.5 * half_deg).deviation, 0.5, 1e-6);
    EXPECT_EQ(read_at(ils, nm * kNm, 3 * half_deg).deviation, 1.0);  // clamped, still valid
    EXPECT_TRUE(read_at(ils, nm * kNm, 3 * half_deg).valid());
  }
  // Sense from the geometry: a point displaced to the left of an aircraft flying the inbound
  // course (towards course - 90 deg) must read fly right.
  const GeoPoint centre = from_localizer(ils, 6 * kNm, 0);
  const GeoPoint to_left = direct(centre, ils.course_true_rad / kDeg - 90, 200, 0);
  const LocalizerReading r =
      LocalizerReceiver().read(ils, pose_at(to_left, on_path_altitude_m(ils, 6 * kNm)));
  EXPECT_GT(r.deviation, 0.0);
  EXPECT_GT(r.angle_off_course_rad, 0.0);
}

TEST(Localizer, CourseWidthFromTheRecordOrLimitedTo6Degrees) {
  IlsApproach ils = ksfo_28r();
  ils.course_width_rad = 5.0 * kDeg;
  EXPECT_NEAR(read_at(ils, 5 * kNm, 2.5).deviation, 1.0, 1e-6);
  EXPECT_NEAR(approach_geometry(ils).course_half_width_rad, 2.5 * kDeg, 1e-12);
  // A short runway: 700 ft at 900 m would be a 13.5 deg course; the rule caps it at 6 deg.
  IlsApproach short_runway = ksfo_28r();
  short_runway.localizer = direct(ils.threshold, ils.course_true_rad / kDeg, 900.0,
                                  ils.localizer.elevation_m);
  EXPECT_NEAR(approach_geometry(short_runway).course_half_width_rad, 3.0 * kDeg, 1e-12);
}

TEST(Localizer, CoverageAndBehindTheAntenna) {
  const IlsApproach ils = ksfo_28r();
  const double at_3000_ft = ils.localizer.elevation_m + 3000 * kFt;
  EXPECT_TRUE(read_at(ils, 17 * kNm, 9, at_3000_ft).valid());
  EXPECT_EQ(read_at(ils, 17 * kNm, 11, at_3000_ft).status, SignalStatus::kOutsideCoverage);
  EXPECT_EQ(read_at(ils, 19 * kNm, 0, at_3000_ft).status, SignalStatus::kOutsideCoverage);
  EXPECT_TRUE(read_at(ils, 9 * kNm, -34, at_3000_ft).valid());
  EXPECT_EQ(read_at(ils, 9 * kNm, -36, at_3000_ft).status, SignalStatus::kOutsideCoverage);
  EXPECT_EQ(read_at(ils, 11 * kNm, 20, at_3000_ft).status, SignalStatus::kOutsideCoverage);
  // The ceiling: 4,500 ft above the antenna or 7 deg up, whichever is higher (3,730 ft at 5 NM,
  // 12,700 ft at 17 NM).
  EXPECT_EQ(read_at(ils, 5 * kNm, 0, ils.localizer.elevation_m + 4600 * kFt).status,
            SignalStatus::kOutsideCoverage);
  EXPECT_TRUE(read_at(ils, 5 * kNm, 0, ils.localizer.elevation_m + 4400 * kFt).valid());
  EXPECT_TRUE(read_at(ils, 17 * kNm, 0, ils.localizer.elevation_m + 12000 * kFt).valid());
  EXPECT_EQ(read_at(ils, 17 * kNm, 0, ils.localizer.elevation_m + 14000 * kFt).status,
            SignalStatus::kOutsideCoverage);
  // Beyond the antenna, on the extended centreline past the stop end: the back course.
  const GeoPoint behind = direct(ils.localizer, ils.course_true_rad / kDeg, 2 * kNm, 0);
  const LocalizerReading r = LocalizerReceiver().read(ils, pose_at(behind, 1000));
  EXPECT_EQ(r.status, SignalStatus::kBehindAntenna);
  EXPECT_EQ(r.deviation, 0.0);
  EXPECT_EQ(read_at(ils, 5 * kNm, 100, at_3000_ft).status, SignalStatus::kBehindAntenna);
}

TEST(Localizer, BadInputs) {
  const IlsApproach ils = ksfo_28r();
  AircraftPose pose = pose_at(ils.threshold, 100);
  pose.lat_rad = 2.0;
  EXPECT_EQ(LocalizerReceiver().read(ils, pose).status, SignalStatus::kInvalidInput);
  IlsApproach broken = ils;
  broken.glide_path_angle_rad = 0.0;
  EXPECT_THROW(LocalizerReceiver().read(broken, pose_at(ils.threshold, 100)), std::invalid_argument);
}

}  // namespace
}  // namespace fedsim::radio::test
