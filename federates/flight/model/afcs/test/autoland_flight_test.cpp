// Closed loop: the 737 pack flown by the AFCS from a 30 deg localizer intercept at 10 NM to an
// automatic landing and rollout on KSFO 28R, in calm air and in a 10 kt crosswind with light
// turbulence, against the figures of the AFCS issue (touchdown within 27 ft of the centreline,
// sink rate below 6 ft/s, 200 to 2,700 ft beyond the threshold, wings level within 5 deg,
// stopped on the runway); and a go-around from 200 ft.
#include "closed_loop_support.hpp"

#include "common/airports/runway_table.hpp"

#include "flight/model/afcs/landing_figures.hpp"

namespace fedsim::flight::afcs::testing {
namespace {

constexpr double kApproachCas = 145.0 * kKt;

WeatherSettings crosswind_10_kt_light_turbulence(double course_rad, std::uint64_t seed) {
  WeatherSettings w;
  w.wind.altitude_m = {0.0, 10000.0};
  w.wind.speed_mps = {10.0 * kKt, 10.0 * kKt};
  w.wind.from_direction_rad = {course_rad + units::kHalfPi, course_rad + units::kHalfPi};  // from the right
  w.turbulence = Turbulence::Severity::kLight;
  w.turbulence_seed = seed;
  return w;
}

/// The autoland from 10 NM, 1.5 km left of the course at 2500 ft on a 30 deg intercept.
std::unique_ptr<ClosedLoopFlight> fly_autoland(const WeatherSettings& weather, int ils_delay_frames = 0) {
  ClosedLoopOptions options;
  options.ils_delay_frames = ils_delay_frames;
  auto f = make_flight(options);
  f->model().set_weather(weather);
  const TrimResult t = f->start_level({10.0 * kNm, 1500.0, 2500.0 * kFt}, f->course_rad() + 30.0 * kDeg,
                                      150.0 * kKt, landing_configuration());
  EXPECT_TRUE(t.converged) << t.reason;
  engage_holding(*f);
  f->mcp().calibrated_airspeed_mps = kApproachCas;
  f->mcp().autobrake_setting = 2;
  f->press(button(&McpButtons::approach));
  f->run_until([](const FlightSample& s) { return s.main_gear_on_ground && s.ground_speed_mps < 0.5; }, 600.0);
  return f;
}

const RunwayCentreline& ksfo_28r_centreline() {
  static const RunwayCentreline runway = RunwayCentreline::from_table(RunwayTable::load_default(), "KSFO", "28R");
  return runway;
}

void print(const char* what, const LandingFigures& l, const ClosedLoopFlight& f) {
  const Touchdown& t = l.touchdown;
  std::printf("%s: touchdown %.0f ft beyond the threshold, %+.2f m from the localizer course (%+.2f m from the "
              "runway centreline), sink %.2f ft/s, bank %+.2f deg, pitch %.2f deg, heading %+.2f deg off the "
              "course, %.1f KCAS; rollout within %.2f m of the course, stopped %.0f m beyond the threshold "
              "(runway %.0f m), %.2f m off; %.0f s flown\n",
              what, t.beyond_threshold_m / kFt, t.left_of_course_m, l.touchdown_left_of_centreline_m,
              t.sink_rate_mps / kFt, t.roll_rad / kDeg, t.pitch_rad / kDeg, t.heading_minus_course_rad / kDeg,
              t.cas_mps / kKt, l.max_rollout_offset_m, l.stop_beyond_threshold_m, l.runway_length_m,
              l.stop_left_of_centreline_m, f.time_s());
}

void expect_within_the_issue_limits(const LandingFigures& l, const ClosedLoopFlight& f) {
  ASSERT_TRUE(l.touched_down);
  const std::vector<std::string> broken = limit_violations(l);
  EXPECT_TRUE(broken.empty()) << broken.front();
  // The same limits written out, against the localizer course as well as the runway.
  const Touchdown& t = l.touchdown;
  EXPECT_LT(std::abs(t.left_of_course_m), 27.0 * kFt);
  EXPECT_LT(std::abs(l.touchdown_left_of_centreline_m), 27.0 * kFt);
  EXPECT_LT(t.sink_rate_mps, 6.0 * kFt);
  EXPECT_GT(t.beyond_threshold_m, 200.0 * kFt);
  EXPECT_LT(t.beyond_threshold_m, 2700.0 * kFt);
  EXPECT_LT(std::abs(t.roll_rad), 5.0 * kDeg);
  EXPECT_TRUE(l.stopped);
  EXPECT_LT(l.stop_beyond_threshold_m, l.runway_length_m);
  EXPECT_LT(l.max_rollout_offset_m, 15.0);  // on the 61 m (200 ft) runway, near its centreline
  // The autoland sequence ran in order and the autopilot stayed engaged.
  const auto& tr = f.transitions();
  using C = ModeTransition::Channel;
  const double loc = time_entered(tr, C::kLateral, "VOR/LOC"), gs = time_entered(tr, C::kVertical, "G/S");
  const double flare = time_entered(tr, C::kVertical, "FLARE"), rollout = time_entered(tr, C::kLateral, "ROLLOUT");
  EXPECT_LT(loc, gs);
  EXPECT_LT(gs, flare);
  EXPECT_LT(flare, rollout);
  EXPECT_LT(time_entered(tr, C::kLateral, "ALIGN"), rollout);
  EXPECT_LT(time_entered(tr, C::kThrust, "RETARD"), rollout);
  EXPECT_TRUE(l.autopilot_engaged);
  EXPECT_EQ(l.alerts, 0u);
}

TEST(LandingFigures, TheRunwayCentrelineIsTheTablesAndTheCourseNowRunsAlongIt) {
  const RunwayCentreline& runway = ksfo_28r_centreline();
  EXPECT_NEAR(runway.length_m(), 3618.0 - 91.0, 5.0);  // runways.csv: 3618 m, 28R displaced 91 m
  const nav::IlsApproach& ils = ksfo_28r();
  EXPECT_NEAR(runway.left_m(ils.threshold.lat_rad, ils.threshold.lon_rad), 0.0, 1e-6);
  EXPECT_NEAR(runway.beyond_threshold_m(ils.threshold.lat_rad, ils.threshold.lon_rad), 0.0, 1e-6);
  // The localizer antenna, 1,000 ft beyond the far end on the extended centreline.
  EXPECT_NEAR(runway.left_m(ils.localizer.lat_rad, ils.localizer.lon_rad), 0.0, 0.5);
  // The course line laid through the threshold stays on the centreline; the record's own does not.
  const GeodeticPosition on_course = approach_point_position(ils, radio::approach_geometry(ils), {-600.0, 0.0, 0.0});
  EXPECT_NEAR(runway.left_m(on_course.lat_rad, on_course.lon_rad), 0.0, 0.1);
  double misalignment = 0.0;
  with_course_through_threshold(ksfo_28r_as_published(), &misalignment);
  std::printf("KSFO 28R in data/nav/ils.csv: true course %.3f deg, the runway's %.3f deg; the record's course line "
              "passes %.2f m from the threshold (ICAO Annex 10 Cat III alignment: 3 m)\n",
              ksfo_28r_as_published().course_true_rad / kDeg, ils.course_true_rad / kDeg, std::abs(misalignment));
  EXPECT_GT(std::abs(misalignment), 3.0);  // the data's mismatch, the reason for the realignment
}

TEST(AutolandInFlight, CalmAir) {
  auto f = fly_autoland(WeatherSettings{});
  maybe_trace(*f, "autoland_calm");
  maybe_print_transitions(*f);
  const LandingFigures l = landing_figures(*f, ksfo_28r_centreline());
  print("Autoland, calm", l, *f);
  expect_within_the_issue_limits(l, *f);
}

TEST(AutolandInFlight, TenKnotCrosswindWithLightTurbulence) {
  auto f = fly_autoland(crosswind_10_kt_light_turbulence(ksfo_28r().course_true_rad, 7));
  maybe_trace(*f, "autoland_crosswind");
  maybe_print_transitions(*f);
  const LandingFigures l = landing_figures(*f, ksfo_28r_centreline());
  print("Autoland, 10 kt crosswind from the right, light turbulence", l, *f);
  expect_within_the_issue_limits(l, *f);
  // The crosswind was there: flown crabbed into it, decrabbed in ALIGN.
  double crab = 0.0;
  for (const FlightSample& s : f->history()) {
    if (s.gear_height_m < 500.0 * kFt && s.gear_height_m > 200.0 * kFt) {
      crab = std::max(crab, wrap_angle_rad(s.heading_rad - f->course_rad()) / kDeg);
    }
  }
  EXPECT_GT(crab, 3.0);  // 10 kt across 145 kt: 4 deg
  EXPECT_LT(std::abs(l.touchdown.heading_minus_course_rad), 2.0 * kDeg);
}

// In the federation the AFCS reads the navigation federate's ILS readings of the state one frame
// older (lockstep: fedsim-nav steps on frame N-1's state): the same autoland with that lag.
TEST(AutolandInFlight, CrosswindWithTheFederationsOneFrameIlsLag) {
  auto f = fly_autoland(crosswind_10_kt_light_turbulence(ksfo_28r().course_true_rad, 7), 1);
  const LandingFigures l = landing_figures(*f, ksfo_28r_centreline());
  print("Autoland, 10 kt crosswind, light turbulence, ILS one frame late", l, *f);
  expect_within_the_issue_limits(l, *f);
}

TEST(ClosedLoopFlight, RefusesAnIlsLagOutsideItsRange) {
  ClosedLoopOptions options;
  options.ils_delay_frames = -1;
  EXPECT_THROW(make_flight(options), std::invalid_argument);
  options.ils_delay_frames = 11;
  EXPECT_THROW(make_flight(options), std::invalid_argument);
}

TEST(AutolandInFlight, GoAroundFrom200FeetClimbsAwayOnTheTrack) {
  auto f = make_flight();
  const TrimResult t = f->start_level({8.0 * kNm, 0.0, 2500.0 * kFt}, f->course_rad(), 150.0 * kKt,
                                      landing_configuration());
  ASSERT_TRUE(t.converged) << t.reason;
  engage_holding(*f);
  f->mcp().calibrated_airspeed_mps = kApproachCas;
  f->mcp().altitude_m = 3000.0 * kFt;  // the missed-approach altitude
  f->press(button(&McpButtons::approach));
  ASSERT_TRUE(f->run_until([](const FlightSample& s) { return s.gear_height_m < 200.0 * kFt; }, 400.0));
  ASSERT_EQ(f->sample().fma.vertical, VerticalMode::kGlideSlope);
  const double ga_s = f->time_s();
  f->press(button(&McpButtons::takeoff_go_around));
  f->run_for(150.0);
  maybe_trace(*f, "go_around");
  maybe_print_transitions(*f);
  const auto& h = f->history();
  const double lowest = min_over(h, ga_s, [](const FlightSample& s) { return s.gear_height_m; });
  const double pitch_max = max_over(h, ga_s, [](const FlightSample& s) { return s.pitch_rad; });
  const double slowest = min_over(h, ga_s, [](const FlightSample& s) { return s.cas_mps; });
  const double climb_60s = [&] {
    for (const FlightSample& s : h) if (s.time_s > ga_s + 60.0) return s.vertical_speed_mps;
    return 0.0;
  }();
  std::printf("Go-around at 200 ft: lowest %.0f ft, pitch up to %.1f deg, slowest %.1f KCAS, climbing %.0f ft/min "
              "after 60 s, then %s at %.0f ft\n",
              lowest / kFt, pitch_max / kDeg, slowest / kKt, climb_60s / kFpm,
              std::string(to_string(f->sample().fma.vertical)).c_str(), f->sample().altitude_m / kFt);
  EXPECT_GT(lowest, 100.0 * kFt);
  EXPECT_FALSE(std::any_of(h.begin(), h.end(), [](const FlightSample& s) { return s.main_gear_on_ground; }));
  EXPECT_LT(pitch_max, 16.0 * kDeg);
  EXPECT_GT(slowest, kApproachCas - 5.0 * kKt);
  EXPECT_NEAR(climb_60s / kFpm, 2000.0, 400.0);
  EXPECT_EQ(f->sample().fma.lateral, LateralMode::kGoAround);
  EXPECT_NEAR(f->sample().altitude_m, 3000.0 * kFt, 30.0 * kFt);  // levelled off at the MCP altitude
  EXPECT_NEAR(wrap_angle_rad(f->sample().track_rad - f->course_rad()) / kDeg, 0.0, 1.0);
}

}  // namespace
}  // namespace fedsim::flight::afcs::testing
