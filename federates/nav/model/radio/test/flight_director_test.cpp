// Flight director: command signs, the coordinated-turn relation behind the bank law, limits,
// validity, and closed loops on a point-mass aircraft that follows the bars (bank and flight
// path with 1 s lags): localizer capture from a 30 deg intercept, glide-slope capture from
// below, altitude capture.
#include "nav/model/radio/flight_director.hpp"

#include "common/radio/glide_slope_receiver.hpp"
#include "common/radio/localizer_receiver.hpp"
#include "common/radio/radio_geometry.hpp"
#include "common/radio/test/station_fixtures.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace fedsim::nav::test {

using namespace fedsim::radio::test;  // the station records and poses (common/radio/test)
namespace {

constexpr double kG = units::kStandardGravityMps2;
constexpr double kV = 60.0;  // m/s, a light aircraft on the approach

FlightDirectorInputs level_flight(double heading_deg) {
  FlightDirectorInputs in;
  in.pose = pose_at(point_deg(37.5, -122.2, 0), 1000.0, heading_deg, kV);
  return in;
}

TEST(FlightDirector, HeadingSelectBanksTowardsTheHeadingAtTheCoordinatedTurnRate) {
  const FlightDirector fd;
  FlightDirectorInputs in = level_flight(90);
  in.lateral_mode = LateralMode::kHeadingSelect;
  in.selected_heading_true_rad = 100 * kDeg;
  const FlightDirectorCommand right = fd.command(in);
  ASSERT_TRUE(right.roll_valid);
  EXPECT_GT(right.roll_command_rad, 0.0);  // right wing down
  // Followed, the bank turns at g tan(phi) / V = error / tau (tau = 5 s).
  EXPECT_NEAR(kG * std::tan(right.roll_command_rad) / kV, 10 * kDeg / 5.0, 1e-12);
  in.selected_heading_true_rad = 80 * kDeg;
  EXPECT_NEAR(fd.command(in).roll_command_rad, -right.roll_command_rad, 1e-12);
  // Limited to 25 deg; the shorter way round across north.
  in.selected_heading_true_rad = 200 * kDeg;
  EXPECT_NEAR(fd.command(in).roll_command_rad, 25 * kDeg, 1e-12);
  in = level_flight(350);
  in.lateral_mode = LateralMode::kHeadingSelect;
  in.selected_heading_true_rad = 10 * kDeg;
  EXPECT_GT(fd.command(in).roll_command_rad, 0.0);
  EXPECT_FALSE(fd.command(in).pitch_valid);  // vertical mode off
}

TEST(FlightDirector, NavTrackInterceptsTowardsTheNeedle) {
  const FlightDirector fd;
  FlightDirectorInputs in = level_flight(298);
  in.lateral_mode = LateralMode::kNavTrack;
  in.course_true_rad = 298 * kDeg;
  in.course_valid = true;
  in.course_deviation = 0.0;
  EXPECT_NEAR(fd.command(in).roll_command_rad, 0.0, 1e-12);
  in.course_deviation = 0.5;  // fly right: a 15 deg intercept to the right
  const double expected = std::atan(kV * (15 * kDeg / 5.0) / kG);
  EXPECT_NEAR(fd.command(in).roll_command_rad, expected, 1e-12);
  in.course_deviation = -0.5;
  EXPECT_NEAR(fd.command(in).roll_command_rad, -expected, 1e-12);
  in.course_deviation = 3.0;  // beyond full scale: the 30 deg intercept
  in.pose.heading_true_rad = 328 * kDeg;
  EXPECT_NEAR(fd.command(in).roll_command_rad, 0.0, 1e-12);
  // Crabbing 10 deg left into wind on the course: with the ground track no correction, with
  // the heading alone a turn (the standing error the track input removes).
  in.course_deviation = 0.0;
  in.pose.heading_true_rad = 288 * kDeg;
  in.ground_track_true_rad = 298 * kDeg;
  EXPECT_NEAR(fd.command(in).roll_command_rad, 0.0, 1e-12);
  in.ground_track_true_rad.reset();
  EXPECT_GT(fd.command(in).roll_command_rad, 0.1);
  // An invalid NAV signal: no lateral command.
  in.course_valid = false;
  EXPECT_FALSE(fd.command(in).roll_valid);
  EXPECT_EQ(fd.command(in).roll_command_rad, 0.0);
}

TEST(FlightDirector, GlideSlopeAndAltitudeCommandsAboutTheCurrentPitch) {
  const FlightDirector fd;
  FlightDirectorInputs in = level_flight(298);
  in.vertical_mode = VerticalMode::kGlideSlopeTrack;
  in.glide_path_angle_rad = 3 * kDeg;
  in.glide_slope_valid = true;
  in.pose.pitch_rad = 1 * kDeg;
  in.pose.climb_rate_mps = -kV * std::sin(3 * kDeg);  // on the path's flight path
  EXPECT_NEAR(fd.command(in).pitch_command_rad, 1 * kDeg, 1e-12);
  in.glide_slope_deviation = 1.0;  // full-scale low: level off, 3 deg more nose up
  EXPECT_NEAR(fd.command(in).pitch_command_rad, 4 * kDeg, 1e-12);
  in.glide_slope_deviation = -1.0;
  EXPECT_NEAR(fd.command(in).pitch_command_rad, -2 * kDeg, 1e-12);
  in.pose.pitch_rad = 14 * kDeg;
  in.glide_slope_deviation = 1.0;
  EXPECT_NEAR(fd.command(in).pitch_command_rad, 15 * kDeg, 1e-12);  // pitch-up limit
  in.glide_slope_valid = false;
  EXPECT_FALSE(fd.command(in).pitch_valid);

  in = level_flight(0);
  in.vertical_mode = VerticalMode::kAltitudeHold;
  in.selected_altitude_msl_m = in.pose.altitude_msl_m + 20.0;  // 2 m/s climb for tau 10 s
  EXPECT_NEAR(fd.command(in).pitch_command_rad, std::asin(2.0 / kV), 1e-12);
  in.selected_altitude_msl_m = in.pose.altitude_msl_m - 1000.0;  // limited to 1000 ft/min
  EXPECT_NEAR(fd.command(in).pitch_command_rad, -std::asin(1000 * units::kFpmToMps / kV), 1e-12);
}

TEST(FlightDirector, InvalidInputsAndGains) {
  const FlightDirector fd;
  FlightDirectorInputs in = level_flight(0);
  in.lateral_mode = LateralMode::kHeadingSelect;
  in.vertical_mode = VerticalMode::kAltitudeHold;
  in.selected_altitude_msl_m = 1000;
  EXPECT_TRUE(fd.command(in).roll_valid);
  EXPECT_TRUE(fd.command(in).pitch_valid);
  in.selected_heading_true_rad = std::nan("");
  EXPECT_FALSE(fd.command(in).roll_valid);
  EXPECT_TRUE(fd.command(in).pitch_valid);
  in.pose.lat_rad = std::nan("");
  EXPECT_FALSE(fd.command(in).pitch_valid);
  FlightDirectorGains gains;
  gains.bank_limit_rad = 100 * kDeg;
  EXPECT_THROW(FlightDirector{gains}, std::invalid_argument);
  gains = {};
  gains.heading_time_constant_s = 0.0;
  EXPECT_THROW(FlightDirector{gains}, std::invalid_argument);
}

// A point-mass aircraft that follows the bars: bank and flight path approach the commands with
// 1 s lags; coordinated turns; constant airspeed and angle of attack.
struct FollowingAircraft {
  GeoPoint position;
  double altitude_m = 0.0;
  double heading_rad = 0.0;
  double bank_rad = 0.0;
  double gamma_rad = 0.0;
  static constexpr double kAlphaRad = 2 * units::kDegToRad;
  static constexpr double kLagS = 1.0;

  radio::AircraftPose pose() const {
    radio::AircraftPose p = pose_at(position, altitude_m, heading_rad / kDeg, kV);
    p.roll_rad = bank_rad;
    p.pitch_rad = gamma_rad + kAlphaRad;
    p.climb_rate_mps = kV * std::sin(gamma_rad);
    return p;
  }
  void step(const FlightDirectorCommand& command, double dt_s) {
    if (command.roll_valid) bank_rad += (command.roll_command_rad - bank_rad) * dt_s / kLagS;
    if (command.pitch_valid) {
      gamma_rad += (command.pitch_command_rad - kAlphaRad - gamma_rad) * dt_s / kLagS;
    }
    heading_rad = radio::wrap_two_pi(heading_rad + kG * std::tan(bank_rad) / kV * dt_s);
    position = direct(position, heading_rad / kDeg, kV * std::cos(gamma_rad) * dt_s, 0);
    altitude_m += kV * std::sin(gamma_rad) * dt_s;
  }
};

TEST(FlightDirectorClosedLoop, CapturesTheLocalizerFromA30DegreeIntercept) {
  const IlsApproach ils = ksfo_28r();
  const FlightDirector fd;
  // 13 NM from the localizer, 1.5 km left of the course (beyond full scale), heading 30 deg right.
  const GeoPoint centre = from_localizer(ils, 13 * kNm, 0);
  FollowingAircraft aircraft{direct(centre, ils.course_true_rad / kDeg - 90, 1500, 0), 600.0,
                             ils.course_true_rad + 30 * kDeg};
  double min_deviation = 1.0;
  double max_bank = 0.0;
  double settled_max = 0.0;
  constexpr double kDt = 0.1;
  for (double t = 0; t < 300.0; t += kDt) {
    const radio::LocalizerReading loc = radio::LocalizerReceiver().read(ils, aircraft.pose());
    ASSERT_TRUE(loc.valid()) << t << " " << to_string(loc.status);
    FlightDirectorInputs in;
    in.pose = aircraft.pose();
    in.lateral_mode = LateralMode::kNavTrack;
    in.course_true_rad = loc.course_true_rad;
    in.course_deviation = loc.deviation;
    in.course_valid = true;
    const FlightDirectorCommand command = fd.command(in);
    min_deviation = std::min(min_deviation, loc.deviation);
    max_bank = std::max(max_bank, std::abs(command.roll_command_rad));
    if (t > 240.0) settled_max = std::max(settled_max, std::abs(loc.deviation));
    aircraft.step(command, kDt);
  }
  EXPECT_LT(settled_max, 0.05);         // on the localizer within 5% of full scale
  EXPECT_GT(min_deviation, -0.3);       // overshoot under 30% of full scale
  EXPECT_LE(max_bank, 25 * kDeg + 1e-12);
}

TEST(FlightDirectorClosedLoop, CapturesTheGlideSlopeFromBelow) {
  const IlsApproach ils = ksfo_28r();
  const FlightDirector fd;
  const double to_threshold_m = inverse(ils.localizer, ils.threshold).distance_m;
  // On the centreline 8 NM from the threshold, level at 1,800 ft above it.
  FollowingAircraft aircraft{from_localizer(ils, to_threshold_m + 8 * kNm, 0),
                             ils.threshold.elevation_m + 1800 * kFt, ils.course_true_rad};
  constexpr double kDt = 0.1;
  double gs_late = 0.0;
  double gamma_late = 0.0;
  int late_samples = 0;
  for (double t = 0; t < 330.0; t += kDt) {
    const radio::LocalizerReading loc = radio::LocalizerReceiver().read(ils, aircraft.pose());
    const radio::GlideSlopeReading gs = radio::GlideSlopeReceiver().read(ils, aircraft.pose());
    ASSERT_TRUE(loc.valid());
    const double from_threshold_m = loc.distance_from_antenna_m - to_threshold_m;
    if (from_threshold_m < 2 * kNm) break;
    FlightDirectorInputs in;
    in.pose = aircraft.pose();
    in.lateral_mode = LateralMode::kNavTrack;
    in.vertical_mode = VerticalMode::kGlideSlopeTrack;
    in.course_true_rad = loc.course_true_rad;
    in.course_deviation = loc.deviation;
    in.course_valid = true;
    in.glide_slope_valid = gs.valid();
    in.glide_slope_deviation = gs.deviation;
    in.glide_path_angle_rad = gs.glide_path_angle_rad;
    aircraft.step(fd.command(in), kDt);  // level (no pitch command) until the GS is valid
    if (from_threshold_m < 3 * kNm) {
      ASSERT_TRUE(gs.valid());
      gs_late = std::max(gs_late, std::abs(gs.deviation));
      gamma_late += aircraft.gamma_rad;
      ++late_samples;
    }
  }
  ASSERT_GT(late_samples, 100);
  EXPECT_LT(gs_late, 0.1);  // within 10% of full scale from 3 to 2 NM
  EXPECT_NEAR(gamma_late / late_samples, -3 * kDeg, 0.3 * kDeg);
}

TEST(FlightDirectorClosedLoop, CapturesASelectedAltitude) {
  const FlightDirector fd;
  FollowingAircraft aircraft{point_deg(37.5, -122.2, 0), 1000.0, 0.0};
  const double target_m = 1000.0 + 500 * kFt;
  double max_climb_mps = 0.0;
  for (double t = 0; t < 180.0; t += 0.1) {
    FlightDirectorInputs in;
    in.pose = aircraft.pose();
    in.vertical_mode = VerticalMode::kAltitudeHold;
    in.selected_altitude_msl_m = target_m;
    aircraft.step(fd.command(in), 0.1);
    max_climb_mps = std::max(max_climb_mps, kV * std::sin(aircraft.gamma_rad));
  }
  EXPECT_NEAR(aircraft.altitude_m, target_m, 3 * kFt);
  EXPECT_LE(max_climb_mps, 1000 * units::kFpmToMps * 1.001);
  EXPECT_GT(max_climb_mps, 900 * units::kFpmToMps);  // it did climb at the limit
}

}  // namespace
}  // namespace fedsim::nav::test
