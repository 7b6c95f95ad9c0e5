// The VOR side of VOR/LOC against independent references: the cross track from common/radio's VOR
// receiver against GeographicLib's geodesics, the capture law's lead on a turn integrated here,
// the nominal distance schedule without DME, and the station-passage cues.
#include "flight/model/afcs/lateral_guidance.hpp"
#include "flight/model/afcs/vor_guidance.hpp"

#include "closed_loop_support.hpp"
#include "common/radio/vor_receiver.hpp"

#include <GeographicLib/Geodesic.hpp>
#include <gtest/gtest.h>

#include <cmath>

namespace fedsim::flight::afcs::testing {
namespace {

constexpr double kDt = 0.02;

/// A VOR at 37.6 N 122.4 W, aligned to 17 deg E.
nav::Navaid vor_station() {
  nav::Navaid n;
  n.ident = "TST";
  n.type = nav::NavaidType::kVorDme;
  n.frequency_khz = 115800;
  n.position = {37.6 * kDeg, -122.4 * kDeg, 4.0};
  n.slaved_variation_rad = 17.0 * kDeg;
  n.slaved_variation_known = true;
  n.power = nav::PowerClass::kHigh;
  n.usage = nav::UsageType::kBoth;
  return n;
}

AfcsVorSignals valid_vor(double deviation, VorToFrom to_from, double course_rad = 0.0) {
  AfcsVorSignals v;
  v.tuned = v.valid = true;
  v.deviation = deviation;
  v.course_true_rad = course_rad;
  v.to_from = to_from;
  return v;
}

TEST(Vor, CrossTrackFromTheDeviationAndDmeMatchesTheGeodesics) {
  // Outbound (FROM) on the 240 radial and inbound (TO) on the same line, points 5-25 NM out and
  // up to 1.5 NM either side: y = d sin(deviation x 10 deg) against the geodesic cross track.
  const nav::Navaid vor = vor_station();
  const auto& geod = GeographicLib::Geodesic::WGS84();
  const double obs = 240.0 * kDeg, course = obs + vor.slaved_variation_rad;
  for (const bool from : {true, false})
  for (const double out_nm : {5.0, 15.0, 25.0})
  for (const double left_nm : {-1.5, -0.4, 0.3, 1.2}) {
    // The point at `out` on the radial, then across: left of the direction flown.
    const double flown = from ? course : course + units::kPi;
    double lat = 0, lon = 0, lat2 = 0, lon2 = 0;
    geod.Direct(vor.position.lat_rad / kDeg, vor.position.lon_rad / kDeg, course / kDeg, out_nm * kNm, lat, lon);
    geod.Direct(lat, lon, (flown - 90.0 * kDeg) / kDeg, left_nm * kNm, lat2, lon2);
    radio::AircraftPose pose;
    pose.lat_rad = lat2 * kDeg;
    pose.lon_rad = lon2 * kDeg;
    pose.altitude_msl_m = 3000.0;
    pose.true_airspeed_mps = 150.0;
    const radio::VorReading r = radio::VorReceiver().read(vor, pose, from ? obs : obs + units::kPi);
    ASSERT_TRUE(r.valid());
    EXPECT_EQ(r.to_from, from ? radio::ToFrom::kFrom : radio::ToFrom::kTo);
    if (std::abs(r.course_deviation) >= 1.0) continue;  // beyond full scale: clamped
    double d = 0, azimuth1 = 0, azimuth2 = 0;
    geod.Inverse(vor.position.lat_rad / kDeg, vor.position.lon_rad / kDeg, lat2, lon2, d, azimuth1, azimuth2);
    const double reference = (from ? 1.0 : -1.0) * d * std::sin(course - azimuth1 * kDeg);
    EXPECT_NEAR(reference, left_nm * kNm, 0.002 * kNm);  // the point is where asked
    const double y = vor_cross_track_left_m(r.course_deviation, 10.0 * kDeg, r.ground_distance_m);
    EXPECT_NEAR(y, reference, 0.002 * std::abs(reference) + 1.0) << from << " " << out_nm << " " << left_nm;
    // The DME's slant range overstates the ground distance by about (h/d)^2 / 2: 5 % at 5 NM
    // from 3000 m above the station, 0.2 % at 25 NM.
    const double slant_y = vor_cross_track_left_m(r.course_deviation, 10.0 * kDeg, r.slant_range_m);
    const double h_over_d = 3000.0 / r.ground_distance_m;
    EXPECT_NEAR(slant_y / y, 1.0 + 0.5 * h_over_d * h_over_d, 0.002);
  }
}

TEST(Vor, CaptureLeadFromTheVorLawEndsTheTurnOnTheCourse) {
  // At 150 m/s the capture turn of the VOR law, within an MCP bank limit of 25 deg (capture bank
  // 20 deg), started at the lead after the lead time, ends on the course.
  const CourseLaw law = vor_course_law(LateralGains{}, VorGains{}, 25.0 * kDeg);
  EXPECT_NEAR(law.capture_bank_rad, 20.0 * kDeg, 1e-12);
  EXPECT_NEAR(law.lead_time_s, 3.0, 1e-12);  // roll-in 2 s + the deviation filter's 1 s
  EXPECT_NEAR(vor_course_law(LateralGains{}, VorGains{}, 10.0 * kDeg).capture_bank_rad, 8.0 * kDeg, 1e-12);
  const double v = 150.0, dt = 0.001;
  for (const double intercept_deg : {30.0, 45.0}) {
    const double intercept = intercept_deg * kDeg;
    const double lead = course_capture_lead_m(intercept, v, law);
    double y = lead, track = intercept;
    for (double t = 0; t < law.lead_time_s; t += dt) y -= v * std::sin(track) * dt;
    const double rate = units::kStandardGravityMps2 * std::tan(law.capture_bank_rad) / v;
    while (track > 0) {
      track -= rate * dt;
      y -= v * std::sin(track) * dt;
    }
    EXPECT_NEAR(y, 0.0, 0.5) << intercept_deg;
    EXPECT_TRUE(course_capture_point(0.3, lead * 0.99, 0.0, intercept, v, law));
    EXPECT_FALSE(course_capture_point(0.3, lead * 1.01, 0.0, intercept, v, law));
  }
  // Its track law: the cross track decays with the VOR's time constant.
  double y = 500.0;
  for (double t = 0; t < law.track_time_constant_s; t += 0.01) {
    y -= v * std::sin(course_track_command_rad(y, 0.0, v, law)) * 0.01;
  }
  EXPECT_NEAR(y, 500.0 * std::exp(-1.0), 2.0);
}

TEST(VorGuidance, UsesTheDmeElseANominalDistanceDeadReckonedAlongTheCourse) {
  const VorGains gains;
  VorGuidance g(gains, kDt);
  AfcsVorSignals v = valid_vor(0.2, VorToFrom::kTo);
  v.dme_valid = true;
  v.dme_slant_range_m = 20000.0;
  EXPECT_DOUBLE_EQ(g.step(v, 150.0, 0.0).distance_m, 20000.0);
  EXPECT_TRUE(g.estimate().distance_from_dme);
  EXPECT_NEAR(g.estimate().cross_track_left_m, 20000.0 * std::sin(0.2 * 10.0 * kDeg), 1e-6);
  // The DME lost: on from its last distance, closing at the speed along the course (TO).
  v.dme_valid = false;
  for (int i = 0; i < 50; ++i) g.step(v, 150.0, 0.0);  // 1 s
  EXPECT_NEAR(g.estimate().distance_m, 20000.0 - 150.0, 1e-6);
  EXPECT_FALSE(g.estimate().distance_from_dme);
  // FROM opens; 60 deg off the course at half the rate; OFF holds.
  v.to_from = VorToFrom::kFrom;
  for (int i = 0; i < 50; ++i) g.step(v, 150.0, 60.0 * kDeg);
  EXPECT_NEAR(g.estimate().distance_m, 20000.0 - 150.0 + 75.0, 1e-6);
  v.to_from = VorToFrom::kOff;
  g.step(v, 150.0, 0.0);
  EXPECT_NEAR(g.estimate().distance_m, 20000.0 - 75.0, 1e-6);
  // After a station passage: the minimum.
  g.station_passed();
  g.step(v, 150.0, 0.0);
  EXPECT_DOUBLE_EQ(g.estimate().distance_m, gains.min_nominal_distance_m);

  // Never a DME: the nominal distance, closing no nearer than the minimum.
  VorGuidance fresh(gains, kDt);
  AfcsVorSignals to = valid_vor(0.0, VorToFrom::kTo);
  EXPECT_NEAR(fresh.step(to, 150.0, 0.0).distance_m, gains.nominal_distance_m - 150.0 * kDt, 1e-6);
  for (int i = 0; i < 20000; ++i) fresh.step(to, 150.0, 0.0);
  EXPECT_DOUBLE_EQ(fresh.estimate().distance_m, gains.min_nominal_distance_m);
  // Retuned (another VOR): the schedule starts again.
  fresh.step(AfcsVorSignals{}, 150.0, 0.0);
  EXPECT_NEAR(fresh.step(to, 150.0, 0.0).distance_m, gains.nominal_distance_m - 150.0 * kDt, 1e-6);
}

TEST(VorGuidance, FlagsAnErraticDeviationAndToTurningFromAndUsesNothingFlagged) {
  VorGuidance g(VorGains{}, kDt);
  // A 45 deg intercept 5 NM out at 150 m/s moves the needle at 0.013 full scale/s: not erratic.
  double deviation = -0.9;
  for (int i = 0; i < 250; ++i) {
    deviation += 0.013 * kDt;
    EXPECT_FALSE(g.step(valid_vor(deviation, VorToFrom::kFrom), 150.0, 0.0).erratic);
  }
  EXPECT_NEAR(g.estimate().deviation, deviation - 0.013 * 1.0, 0.002);  // the 1 s filter's lag
  // Over the station the bearing swings: 0.5 full scale/s is.
  bool erratic = false;
  for (int i = 0; i < 50; ++i) {
    deviation -= 0.5 * kDt;
    erratic |= g.step(valid_vor(deviation, VorToFrom::kFrom), 150.0, 0.0).erratic;
  }
  EXPECT_TRUE(erratic);
  // TO turning FROM, also across a flag and an OFF.
  VorGuidance p(VorGains{}, kDt);
  EXPECT_FALSE(p.step(valid_vor(0.0, VorToFrom::kTo, 1.0), 150.0, 1.0).passed_station);
  AfcsVorSignals cone;
  cone.tuned = cone.cone_of_confusion = true;
  EXPECT_FALSE(p.step(cone, 150.0, 1.0).valid);
  EXPECT_DOUBLE_EQ(p.estimate().deviation, 0.0);
  EXPECT_DOUBLE_EQ(p.estimate().course_true_rad, 1.0);  // the last valid course
  EXPECT_FALSE(p.step(valid_vor(0.0, VorToFrom::kOff, 1.0), 150.0, 1.0).passed_station);
  EXPECT_TRUE(p.step(valid_vor(0.0, VorToFrom::kFrom, 1.0), 150.0, 1.0).passed_station);
  EXPECT_FALSE(p.step(valid_vor(0.0, VorToFrom::kFrom, 1.0), 150.0, 1.0).passed_station);  // once
  // A first reading after a flag: no rate from the gap.
  p.step(cone, 150.0, 1.0);
  EXPECT_FALSE(p.step(valid_vor(0.9, VorToFrom::kFrom, 1.0), 150.0, 1.0).erratic);
  EXPECT_DOUBLE_EQ(p.estimate().deviation, 0.9);
}

}  // namespace
}  // namespace fedsim::flight::afcs::testing
