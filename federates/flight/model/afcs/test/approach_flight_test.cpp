// Closed loop on the KSFO 28R ILS (data/nav/ils.csv through common/radio's receivers), the 737
// pack flown by the AFCS: localizer capture from a 30 deg intercept, glide-slope capture from
// below and above and tracking, no pitch oscillation after capture, no climb or descent to a new
// MCP altitude on the glide slope, and the flagged signals. Figures of the AFCS issue: LOC
// capture within 1 dot past the centreline, G/S tracking within 0.25 dot below 1000 ft.
#include "closed_loop_support.hpp"

namespace fedsim::flight::afcs::testing {
namespace {

constexpr double kApproachCas = 145.0 * kKt;

/// Landing configuration, level at `altitude_ft`, `before_nm` before the threshold and
/// `left_m` left of the course, heading `intercept_deg` to the right of the course (towards it
/// when left), ALT HLD and SPEED 145 KCAS engaged.
std::unique_ptr<ClosedLoopFlight> on_intercept(double before_nm, double left_m, double altitude_ft,
                                               double intercept_deg) {
  auto f = make_flight();
  const TrimResult t = f->start_level({before_nm * kNm, left_m, altitude_ft * kFt},
                                      f->course_rad() + intercept_deg * kDeg, 150 * kKt, landing_configuration());
  EXPECT_TRUE(t.converged) << t.reason;
  engage_holding(*f);
  f->mcp().calibrated_airspeed_mps = kApproachCas;
  return f;
}

/// The largest localizer deviation (dots) on the far side of the course after the first
/// crossing, for an aircraft starting on side `side` (+1 left of course: deviation +).
double overshoot_dots(const std::vector<FlightSample>& h, double side) {
  bool crossed = false;
  double worst = 0.0;
  for (const FlightSample& s : h) {
    if (!s.localizer_valid) continue;
    if (!crossed && side * s.localizer_deviation < 0.0) crossed = true;
    if (crossed) worst = std::max(worst, -side * s.localizer_deviation * kDotsPerFullScale);
  }
  return worst;
}

TEST(ApproachInFlight, LocalizerCaptureFrom30DegreesPassesLessThanOneDotBeyondTheCentreline) {
  // 12 NM out, 2.5 km off the course, converging at 30 deg from either side; and at 45 deg (the
  // capture turn's lead, 600 m at 150 KTAS, still lies on the localizer's scale there).
  for (const double intercept : {30.0, 45.0})
  for (const double side : {+1.0, -1.0}) {
    auto f = on_intercept(12.0, side * 2500.0, 2000.0, side * intercept);
    f->press(button(&McpButtons::vor_localizer));
    f->run_for(150.0);
    maybe_trace(*f, std::string(side > 0 ? "loc_capture_from_left_" : "loc_capture_from_right_") +
                        std::to_string(static_cast<int>(intercept)));
    maybe_print_transitions(*f);
    const double capture_s = time_entered(f->transitions(), ModeTransition::Channel::kLateral, "VOR/LOC");
    ASSERT_FALSE(std::isnan(capture_s));
    const FlightSample& at_capture = f->history()[static_cast<std::size_t>(capture_s / 0.02)];
    const double overshoot = overshoot_dots(f->history(), side);
    const double settled = max_over(f->history(), capture_s + 60.0,
                                    [](const FlightSample& s) { return std::abs(s.localizer_deviation); });
    std::printf("LOC capture, %.0f deg intercept from the %s: captured %.0f m off the course (%.2f dots), "
                "overshoot %.3f dots (%.1f m), within %.3f dots from 60 s after capture\n",
                intercept, side > 0 ? "left" : "right", std::abs(at_capture.left_of_course_m),
                std::abs(at_capture.localizer_deviation) * kDotsPerFullScale, overshoot,
                max_over(f->history(), capture_s, [&](const FlightSample& s) { return -side * s.left_of_course_m; }),
                settled * kDotsPerFullScale);
    EXPECT_LT(overshoot, 1.0);
    EXPECT_LT(settled * kDotsPerFullScale, 0.05);
    EXPECT_EQ(f->sample().fma.lateral, LateralMode::kLocalizer);
  }
}

/// Established on the localizer at `altitude_ft`, APP armed; the capture and what follows.
struct GlideSlopeRun {
  std::unique_ptr<ClosedLoopFlight> flight;
  double capture_s = NAN;
};

GlideSlopeRun glide_slope_run(double before_nm, double altitude_ft, double vertical_speed_fpm) {
  GlideSlopeRun run;
  run.flight = on_intercept(before_nm, 0.0, altitude_ft, 0.0);
  ClosedLoopFlight& f = *run.flight;
  f.press(button(&McpButtons::approach));
  if (vertical_speed_fpm != 0.0) {
    f.mcp().vertical_speed_mps = vertical_speed_fpm * kFpm;
    f.mcp().altitude_m = 0.0;
    f.press(button(&McpButtons::vertical_speed));
  }
  f.run_until([](const FlightSample& s) { return s.fma.vertical == VerticalMode::kGlideSlope; }, 300.0);
  run.capture_s = f.time_s();
  return run;
}

/// The glide-slope deviation's extreme (dots) from `gear_height_ft` down to 100 ft.
double tracking_dots(const std::vector<FlightSample>& h, double from_height_ft) {
  double worst = 0.0;
  for (const FlightSample& s : h) {
    if (s.gear_height_m < from_height_ft * kFt && s.gear_height_m > 100.0 * kFt && s.fma.vertical == VerticalMode::kGlideSlope) {
      worst = std::max(worst, std::abs(s.glide_slope_deviation) * kDotsPerFullScale);
    }
  }
  return worst;
}

TEST(ApproachInFlight, GlideSlopeCaptureFromBelowWithoutPitchOscillationThenTracks) {
  GlideSlopeRun run = glide_slope_run(11.0, 2000.0, 0.0);
  ClosedLoopFlight& f = *run.flight;
  ASSERT_EQ(f.sample().fma.vertical, VerticalMode::kGlideSlope);
  const double deviation_at_capture = f.sample().glide_slope_deviation;
  // A new MCP altitude above, then below: the glide slope is held (the approach is locked).
  f.run_for(20.0);
  f.mcp().altitude_m = 5000.0 * kFt;
  f.run_for(20.0);
  f.mcp().altitude_m = 0.0;
  f.run_until([](const FlightSample& s) { return s.gear_height_m < 100.0 * kFt; }, 400.0);
  maybe_trace(f, "gs_capture_from_below");
  maybe_print_transitions(f);
  const auto& h = f.history();
  // Pitch after capture: the level-to-descent change, then no oscillation. Count the reversals
  // of the pitch-rate sign larger than 0.5 deg of swing once established (15 s after capture).
  double pitch_max = -INFINITY, pitch_min = INFINITY;
  for (const FlightSample& s : h) {
    if (s.time_s < run.capture_s + 15.0 || s.gear_height_m < 200.0 * kFt) continue;
    pitch_max = std::max(pitch_max, s.pitch_rad / kDeg);
    pitch_min = std::min(pitch_min, s.pitch_rad / kDeg);
  }
  const double overshoot_below_path =
      max_over(h, run.capture_s, [](const FlightSample& s) { return -s.glide_slope_deviation * kDotsPerFullScale; });
  const double tracking = tracking_dots(h, 1000.0);
  std::printf("G/S capture from below at %.2f dots: passes %.3f dots above the path, pitch within %.2f deg once "
              "established, tracking within %.3f dots from 1000 to 100 ft\n",
              deviation_at_capture * kDotsPerFullScale, std::max(overshoot_below_path, 0.0), pitch_max - pitch_min,
              tracking);
  EXPECT_GT(deviation_at_capture, 0.0);  // below the path at capture
  EXPECT_LT(overshoot_below_path, 0.25);
  EXPECT_LT(pitch_max - pitch_min, 1.0);  // no pitch oscillation
  EXPECT_LT(tracking, 0.25);
  // The new MCP altitudes changed nothing.
  EXPECT_FALSE(f.sample().fma.vertical_armed.altitude_capture);
  for (const FlightSample& s : h) {
    if (s.time_s > run.capture_s) EXPECT_EQ(s.fma.vertical, VerticalMode::kGlideSlope) << s.time_s;
  }
}

TEST(ApproachInFlight, GlideSlopeCaptureFromAboveThenTracks) {
  // 9 NM out at 4000 ft (the path is at 2900 ft there), descending at 1500 ft/min with APP armed.
  GlideSlopeRun run = glide_slope_run(9.0, 4000.0, -1500.0);
  ClosedLoopFlight& f = *run.flight;
  ASSERT_EQ(f.sample().fma.vertical, VerticalMode::kGlideSlope);
  const double deviation_at_capture = f.sample().glide_slope_deviation;
  f.run_until([](const FlightSample& s) { return s.gear_height_m < 100.0 * kFt; }, 400.0);
  maybe_trace(f, "gs_capture_from_above");
  const auto& h = f.history();
  const double overshoot_below =
      max_over(h, run.capture_s, [](const FlightSample& s) { return s.glide_slope_deviation * kDotsPerFullScale; });
  const double tracking = tracking_dots(h, 1000.0);
  std::printf("G/S capture from above at %.2f dots: passes %.3f dots below the path, tracking within %.3f dots "
              "from 1000 to 100 ft\n",
              deviation_at_capture * kDotsPerFullScale, std::max(overshoot_below, 0.0), tracking);
  EXPECT_LT(deviation_at_capture, 0.0);  // above the path at capture
  EXPECT_LT(overshoot_below, 0.25);
  EXPECT_LT(tracking, 0.25);
}

TEST(ApproachInFlight, AFlaggedLocalizerDisengagesWithAnAlertAndIsNotFlown) {
  GlideSlopeRun run = glide_slope_run(11.0, 2000.0, 0.0);
  ClosedLoopFlight& f = *run.flight;
  f.run_for(10.0);
  f.set_localizer_off_air(true);
  f.step();
  EXPECT_FALSE(f.sample().fma.autopilot_engaged);
  EXPECT_TRUE(f.sample().fma.alerts & kAlertLocalizerInvalid);
  EXPECT_TRUE(f.sample().fma.alerts & kAlertAutopilotDisconnect);
  EXPECT_NE(f.sample().fma.lateral, LateralMode::kLocalizer);
  // Back on the air it is not captured again until armed again (and the alert stays latched).
  f.set_localizer_off_air(false);
  f.run_for(5.0);
  EXPECT_FALSE(f.sample().fma.autopilot_engaged);
  EXPECT_TRUE(f.sample().fma.alerts & kAlertAutopilotDisconnect);
}

TEST(ApproachInFlight, AFlaggedGlideSlopeDisengagesWithAnAlert) {
  GlideSlopeRun run = glide_slope_run(11.0, 2000.0, 0.0);
  ClosedLoopFlight& f = *run.flight;
  f.run_for(10.0);
  f.set_glide_slope_off_air(true);
  f.step();
  EXPECT_FALSE(f.sample().fma.autopilot_engaged);
  EXPECT_TRUE(f.sample().fma.alerts & kAlertGlideSlopeInvalid);
  EXPECT_EQ(f.sample().fma.lateral, LateralMode::kLocalizer);  // the FD keeps the localizer
  EXPECT_EQ(f.sample().fma.vertical, VerticalMode::kPitchAttitude);
}

}  // namespace
}  // namespace fedsim::flight::afcs::testing
