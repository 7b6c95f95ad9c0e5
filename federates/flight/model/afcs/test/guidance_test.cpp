// The guidance laws against independent references: kinematics integrated here, the ILS
// geometry from GeographicLib, and closed-form solutions.
#include "flight/model/afcs/lateral_guidance.hpp"
#include "flight/model/afcs/vertical_guidance.hpp"

#include "closed_loop_support.hpp"
#include "common/radio/approach_geometry.hpp"
#include "common/radio/glide_slope_receiver.hpp"
#include "common/radio/localizer_receiver.hpp"

#include <GeographicLib/LocalCartesian.hpp>
#include <gtest/gtest.h>

#include <cmath>

namespace fedsim::flight::afcs::testing {
namespace {

constexpr double kG = units::kStandardGravityMps2;

TEST(AltitudeCapture, LevelsOffWithoutOvershootWithinTheAccelerationLimit) {
  const AltitudeGains gains;
  for (const double rate_fpm : {500.0, 2000.0, 4000.0}) {
    // Climbing at rate towards 1000 m: from the capture point on, an aircraft whose climb rate
    // follows the law exactly (the ideal path loop).
    const double target = 1000.0, dt = 0.01;
    double h = 0.0, hdot = rate_fpm * kFpm;
    while (!altitude_capture_point(target - h, hdot, gains)) h += hdot * dt;
    const double capture_distance = target - h;
    double max_accel = 0.0, max_h = h, previous = hdot;
    for (int i = 0; i < 20000; ++i) {
      hdot = altitude_rate_command_mps(target - h, gains);
      max_accel = std::max(max_accel, std::abs(hdot - previous) / dt);
      previous = hdot;
      h += hdot * dt;
      max_h = std::max(max_h, h);
    }
    EXPECT_LE(max_h, target) << rate_fpm;  // no overshoot
    EXPECT_NEAR(h, target, 0.01) << rate_fpm;
    EXPECT_LT(max_accel, gains.capture_acceleration_mps2 * 1.05) << rate_fpm;
    // Started where the level-off needs it: sqrt((a tau)^2 + 2 a dh) - a tau = v at
    // dh = v^2 / (2 a) + v tau.
    const double v = rate_fpm * kFpm;
    const double expected = v * v / (2 * gains.capture_acceleration_mps2) + v * gains.time_constant_s;
    EXPECT_NEAR(capture_distance, expected, v * dt + 1e-6) << rate_fpm;
  }
  // Moving away from the target: never a capture point.
  EXPECT_FALSE(altitude_capture_point(10.0, -5.0, gains));
}

TEST(GlideSlope, HeightErrorFromTheDeviationMatchesTheGeometry) {
  const nav::IlsApproach& ils = ksfo_28r();
  const nav::GeoPoint& gs = ils.glide_slope;
  const GeographicLib::LocalCartesian antenna(gs.lat_rad / kDeg, gs.lon_rad / kDeg, gs.elevation_m);
  for (const double distance : {2000.0, 6000.0, 12000.0}) {
    for (const double below : {-20.0, -5.0, 5.0, 20.0}) {
      // A point on the approach side at this horizontal distance, `below` m under the path.
      const double azimuth = ils.course_true_rad + units::kPi;
      const double east = distance * std::sin(azimuth), north = distance * std::cos(azimuth);
      const double up = distance * std::tan(ils.glide_path_angle_rad) - below;
      double lat = 0, lon = 0, h = 0;
      antenna.Reverse(east, north, up, lat, lon, h);
      radio::AircraftPose pose;
      pose.lat_rad = lat * kDeg;
      pose.lon_rad = lon * kDeg;
      pose.altitude_msl_m = h;
      pose.heading_true_rad = ils.course_true_rad;
      pose.true_airspeed_mps = 70.0;
      const radio::GlideSlopeReading r = radio::GlideSlopeReceiver().read(ils, pose);
      ASSERT_TRUE(r.valid()) << distance << " " << below;
      const double e = glide_path_height_error_m(r.deviation, r.glide_path_angle_rad, r.distance_from_antenna_m);
      EXPECT_NEAR(e, below, 0.02 * std::abs(below) + 0.1) << distance << " " << below;
    }
  }
}

TEST(GlideSlope, CaptureFromBelowAtTheLawsLevelPoint) {
  const GlideSlopeGains gains;
  const double theta = 3.0 * kDeg, v = 75.0;
  // Level flight: the law asks for a level path when e = V tau tan(theta) (38 m at 75 m/s).
  const double level_point = v * gains.path_time_constant_s * std::tan(theta);
  // deviation for a given height error at 9 km: e / (0.24 theta d)
  auto deviation = [&](double e) { return e / (0.24 * theta * 9000.0); };
  EXPECT_FALSE(glide_slope_capture_point(deviation(level_point * 1.3), level_point * 1.3, theta, v, 0.0, gains));
  EXPECT_TRUE(glide_slope_capture_point(deviation(level_point * 0.95), level_point * 0.95, theta, v, 0.0, gains));
  // At the capture the command is within the margin of the present (level) path.
  EXPECT_NEAR(glide_slope_path_command_rad(level_point, theta, v, gains), 0.0, 1e-9);
  // From above, descending at 5 deg: captured once the law asks for no more than 5 deg.
  const double above_point = -v * gains.path_time_constant_s * std::tan(2.0 * kDeg);
  EXPECT_FALSE(glide_slope_capture_point(deviation(above_point * 1.5), above_point * 1.5, theta, v, -5.0 * kDeg, gains));
  EXPECT_TRUE(glide_slope_capture_point(deviation(above_point * 0.8), above_point * 0.8, theta, v, -5.0 * kDeg, gains));
  // Off scale: never.
  EXPECT_FALSE(glide_slope_capture_point(1.0, level_point, theta, v, 0.0, gains));
  // Limits: never a climb, never steeper than twice the path.
  EXPECT_EQ(glide_slope_path_command_rad(500.0, theta, v, gains), 0.0);
  EXPECT_NEAR(glide_slope_path_command_rad(-500.0, theta, v, gains), -2.0 * theta, 1e-12);
}

TEST(Localizer, CrossTrackFromTheDeviationMatchesTheCourseGeometry) {
  const nav::IlsApproach& ils = ksfo_28r();
  const radio::ApproachGeometry geometry = radio::approach_geometry(ils);
  for (const double before : {1000.0, 8000.0, 16000.0}) {
    for (const double left : {-150.0, -30.0, 40.0, 200.0}) {
      const GeodeticPosition p = approach_point_position(ils, geometry, {before, left, 500.0});
      radio::AircraftPose pose;
      pose.lat_rad = p.lat_rad;
      pose.lon_rad = p.lon_rad;
      pose.altitude_msl_m = 500.0;
      pose.heading_true_rad = ils.course_true_rad;
      pose.true_airspeed_mps = 70.0;
      const radio::LocalizerReading r = radio::LocalizerReceiver().read(ils, pose);
      ASSERT_TRUE(r.valid());
      if (std::abs(r.deviation) >= 1.0) continue;  // beyond full scale: clamped
      const double y = localizer_cross_track_left_m(r.deviation, r.course_half_width_rad, r.distance_from_antenna_m);
      const double reference = radio::course_coordinates(ils, geometry, p.lat_rad, p.lon_rad).left_m;
      EXPECT_NEAR(y, reference, 0.005 * std::abs(reference) + 0.5) << before << " " << left;
      EXPECT_NEAR(reference, left, 0.01);  // the helper places the point where asked
    }
  }
}

TEST(Localizer, CaptureTurnFromTheLeadPointEndsOnTheCourse) {
  // A point-mass aircraft at 75 m/s intercepting at 30 and 45 deg: it flies straight for the
  // roll-in time, then turns at the capture bank's rate g tan(phi) / V until on the course.
  // Starting the turn at the computed lead puts it on the centreline when the turn ends.
  const LateralGains gains;
  const double v = 75.0, dt = 0.001;
  for (const double intercept_deg : {30.0, 45.0, 60.0}) {
    const double intercept = intercept_deg * kDeg;
    const double lead = localizer_capture_lead_m(intercept, v, gains);
    double y = lead, track = intercept;  // track relative to the course, + towards it
    for (double t = 0; t < gains.roll_in_time_s; t += dt) y -= v * std::sin(track) * dt;
    const double rate = kG * std::tan(gains.capture_bank_rad) / v;
    while (track > 0) {
      track -= rate * dt;
      y -= v * std::sin(track) * dt;
    }
    EXPECT_NEAR(y, 0.0, 0.5) << intercept_deg;
    // Left of the course (y > 0) with the track right of it (+): closing.
    EXPECT_TRUE(localizer_capture_point(0.5, lead * 0.99, 0.0, intercept, v, gains)) << intercept_deg;
    EXPECT_FALSE(localizer_capture_point(0.5, lead * 1.01, 0.0, intercept, v, gains)) << intercept_deg;
    EXPECT_TRUE(localizer_capture_point(-0.5, -lead * 0.99, 0.0, -intercept, v, gains)) << intercept_deg;
  }
  // Diverging: no capture; off scale: no capture.
  EXPECT_FALSE(localizer_capture_point(0.5, 100.0, 0.0, -30.0 * kDeg, v, gains));
  EXPECT_FALSE(localizer_capture_point(1.0, 100.0, 0.0, 30.0 * kDeg, v, gains));
}

TEST(Localizer, TrackLawDecaysTheCrossTrackExponentially) {
  // Flying the commanded track exactly: dy/dt = -V sin(track - course) = -y / tau.
  const LateralGains gains;
  const double v = 75.0, dt = 0.01, tau = gains.localizer_time_constant_s;
  double y = 200.0;
  for (double t = 0; t < tau; t += dt) {
    const double track = localizer_track_command_rad(y, 0.0, v, gains);
    y -= v * std::sin(track) * dt;  // y is left of course; a track to the right reduces it
  }
  EXPECT_NEAR(y, 200.0 * std::exp(-1.0), 1.0);
  // The intercept is limited.
  EXPECT_NEAR(localizer_track_command_rad(1e5, 0.0, v, gains), gains.max_intercept_rad, 1e-12);
}

TEST(BankForDirection, IsTheCoordinatedTurnThatClosesTheErrorAtOneOverTau) {
  const double v = 100.0, tau = 5.0, error = 10.0 * kDeg;
  const double bank = bank_for_direction_error_rad(error, v, tau, 30.0 * kDeg);
  EXPECT_NEAR(kG * std::tan(bank) / v, error / tau, 1e-12);
  EXPECT_EQ(bank_for_direction_error_rad(170.0 * kDeg, v, tau, 25.0 * kDeg), 25.0 * kDeg);
  EXPECT_EQ(bank_for_direction_error_rad(190.0 * kDeg, v, tau, 25.0 * kDeg), -25.0 * kDeg);  // the short way
}

TEST(Flare, ExponentialLawStartsAtTheEntrySinkRateAndMatchesItsSolution) {
  const AutolandGains gains;
  const double h0 = gains.flare_height_m, hdot0 = -3.8;
  const FlareLaw law = FlareLaw::at_entry(h0, hdot0, gains);
  EXPECT_NEAR(law.climb_rate_command_mps(h0), hdot0, 1e-12);  // no step at entry
  // h(t) = (h0 + s tau) exp(-t / tau) - s tau: reaches 0 at t = tau ln(1 + h0 / (s tau)).
  const double s = gains.touchdown_sink_rate_mps, tau = law.time_constant_s;
  const double t_touch = tau * std::log(1.0 + h0 / (s * tau));
  double h = h0, t = 0.0;
  const double dt = 1e-4;
  while (h > 0.0) {
    h += law.climb_rate_command_mps(h) * dt;
    t += dt;
  }
  EXPECT_NEAR(t, t_touch, 1e-3);
  EXPECT_NEAR(law.climb_rate_command_mps(0.0), -s, 1e-12);
}

}  // namespace
}  // namespace fedsim::flight::afcs::testing
