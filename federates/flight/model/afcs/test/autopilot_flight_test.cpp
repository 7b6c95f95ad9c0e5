// Closed loop, the 737 pack flown by the AFCS (no DDS): altitude hold in a 30 deg bank turn,
// a 90 deg heading change and an altitude capture from 2000 ft/min, against the figures of the
// AFCS issue: +-20 ft, overshoot < 2 deg, overshoot < 50 ft.
#include "closed_loop_support.hpp"

namespace fedsim::flight::afcs::testing {
namespace {

/// Clean, 250 KCAS at 10,000 ft (about 290 KTAS), heading north-west over the bay.
std::unique_ptr<ClosedLoopFlight> clean_at_10000_ft(double heading_rad) {
  ClosedLoopOptions o;
  if (std::getenv("NOTRIM")) o.afcs.auto_trim = false;
  auto f = make_flight(o);
  const TrimResult t = f->start_level({30 * kNm, 0.0, 10000 * kFt}, heading_rad, 290 * kKt, clean_configuration());
  EXPECT_TRUE(t.converged) << t.reason;
  engage_holding(*f);
  return f;
}

struct TurnFigures {
  double max_altitude_error_ft = 0.0;
  double time_at_30_deg_bank_s = 0.0;
  double final_heading_error_deg = 0.0;
};

TurnFigures turn_through(ClosedLoopFlight& f, double turn_deg, bool hold_altitude) {
  const double h0 = f.sample().altitude_m, start = f.time_s();
  if (!hold_altitude) f.press(button(&McpButtons::control_wheel_steering));  // CWS P instead
  f.mcp().bank_limit_rad = 30.0 * kDeg;
  f.mcp().heading_true_rad = f.sample().heading_rad + turn_deg * kDeg;
  f.press(button(&McpButtons::heading_select));
  f.run_for(std::abs(turn_deg) / 2.0 + 40.0);
  TurnFigures out;
  for (const FlightSample& s : f.history()) {
    if (s.time_s < start) continue;
    out.max_altitude_error_ft = std::max(out.max_altitude_error_ft, std::abs(s.altitude_m - h0) / kFt);
    if (std::abs(s.roll_rad) > 29.0 * kDeg) out.time_at_30_deg_bank_s += 0.02;
  }
  out.final_heading_error_deg = wrap_angle_rad(f.sample().heading_rad - f.mcp().heading_true_rad) / kDeg;
  return out;
}

TEST(AutopilotInFlight, AltitudeHoldWithin20FeetInA30DegreeBankTurn) {
  for (const double turn : {+170.0, -170.0}) {
    auto f = clean_at_10000_ft(300.0 * kDeg);
    const TurnFigures t = turn_through(*f, turn, true);
    maybe_trace(*f, turn > 0 ? "altitude_hold_turn_right" : "altitude_hold_turn_left");
    std::printf("ALT HOLD, HDG SEL %+.0f deg at 30 deg bank (250 KCAS, 10,000 ft): altitude within %.1f ft, "
                "%.0f s beyond 29 deg of bank, heading %+.2f deg off at the end\n",
                turn, t.max_altitude_error_ft, t.time_at_30_deg_bank_s, t.final_heading_error_deg);
    EXPECT_LT(t.max_altitude_error_ft, 20.0);
    EXPECT_GT(t.time_at_30_deg_bank_s, 30.0);  // it was a 30 deg bank turn
    EXPECT_LT(std::abs(t.final_heading_error_deg), 1.0);
    EXPECT_EQ(f->sample().fma.vertical, VerticalMode::kAltitudeHold);
  }
  // Negative control: the same turn holding the pitch attitude (CWS P) loses height.
  auto f = clean_at_10000_ft(300.0 * kDeg);
  const TurnFigures attitude_only = turn_through(*f, 170.0, false);
  EXPECT_GT(attitude_only.max_altitude_error_ft, 100.0);
}

TEST(AutopilotInFlight, HeadingChangeOf90DegreesOvershootsLessThan2Degrees) {
  for (const double change : {+90.0, -90.0}) {
    auto f = clean_at_10000_ft(300.0 * kDeg);
    const double target = wrap_angle_rad(300.0 * kDeg + change * kDeg);
    f->mcp().heading_true_rad = target;
    f->press(button(&McpButtons::heading_select));
    const double start = f->time_s();
    f->run_for(120.0);
    maybe_trace(*f, change > 0 ? "heading_right_90" : "heading_left_90");
    double overshoot = 0.0, settle_s = NAN;
    for (const FlightSample& s : f->history()) {
      if (s.time_s < start) continue;
      const double beyond = (change > 0 ? 1.0 : -1.0) * wrap_angle_rad(s.heading_rad - target) / kDeg;
      overshoot = std::max(overshoot, beyond);
      if (std::isnan(settle_s) && std::abs(beyond) < 1.0) settle_s = s.time_s - start;
    }
    std::printf("HDG SEL %+.0f deg (250 KCAS, 25 deg bank limit): overshoot %.2f deg, within 1 deg after %.1f s\n",
                change, overshoot, settle_s);
    EXPECT_LT(overshoot, 2.0);
    EXPECT_LT(settle_s, 75.0);  // 1.8 deg/s at 25 deg bank and 290 KTAS: 50 s of turning
    EXPECT_NEAR(wrap_angle_rad(f->sample().heading_rad - target) / kDeg, 0.0, 0.5);
  }
}

TEST(AutopilotInFlight, AltitudeCaptureFrom2000FeetPerMinuteOvershootsLessThan50Feet) {
  for (const double rate_fpm : {+2000.0, -2000.0}) {
    auto f = clean_at_10000_ft(300.0 * kDeg);
    const double target = (10000.0 + (rate_fpm > 0 ? 3000.0 : -3000.0)) * kFt;
    f->mcp().altitude_m = target;
    f->mcp().vertical_speed_mps = rate_fpm * kFpm;
    f->press(button(&McpButtons::vertical_speed));
    const double start = f->time_s();
    ASSERT_TRUE(f->run_until([](const FlightSample& s) { return s.fma.vertical == VerticalMode::kAltitudeHold; },
                             300.0));
    f->run_for(60.0);
    maybe_trace(*f, rate_fpm > 0 ? "altitude_capture_climb" : "altitude_capture_descent");
    maybe_print_transitions(*f);
    const double sign = rate_fpm > 0 ? 1.0 : -1.0;
    double overshoot_ft = -INFINITY, steady_rate_fpm = 0.0, max_accel_g = 0.0;
    const double capture_s = time_entered(f->transitions(), ModeTransition::Channel::kVertical, "ALT ACQ");
    const auto& h = f->history();
    for (std::size_t i = 1; i < h.size(); ++i) {
      if (h[i].time_s < start) continue;
      overshoot_ft = std::max(overshoot_ft, sign * (h[i].altitude_m - target) / kFt);
      if (h[i].time_s < capture_s - 1.0) steady_rate_fpm = h[i].vertical_speed_mps / kFpm;
      if (h[i].time_s > capture_s) {
        max_accel_g = std::max(max_accel_g, std::abs(h[i].vertical_speed_mps - h[i - 1].vertical_speed_mps) /
                                                (0.02 * units::kStandardGravityMps2));
      }
    }
    std::printf("V/S %+.0f ft/min to %.0f ft: flown %+.0f ft/min, ALT ACQ %.0f ft before, overshoot %.1f ft, "
                "level-off within %.3f g\n",
                rate_fpm, target / kFt, steady_rate_fpm,
                std::abs(target - f->history()[static_cast<std::size_t>(capture_s / 0.02)].altitude_m) / kFt,
                std::max(overshoot_ft, 0.0), max_accel_g);
    EXPECT_NEAR(steady_rate_fpm, rate_fpm, 150.0);
    EXPECT_LT(overshoot_ft, 50.0);
    EXPECT_NEAR(f->sample().altitude_m, target, 20.0 * kFt);
    EXPECT_LT(max_accel_g, 0.15);  // a level-off, not a pull-up
  }
}

}  // namespace
}  // namespace fedsim::flight::afcs::testing
