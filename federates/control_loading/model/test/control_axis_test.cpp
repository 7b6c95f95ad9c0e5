// One control-loading axis against hand and analytic results: the static force gradient at two
// dynamic pressures, breakout, the free oscillation of the mass-spring-damper (viscous and
// Coulomb), the end stops, back-drive, trim.
#include "control_loading/model/control_axis.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <stdexcept>
#include <vector>

#include "common/units/units.hpp"

namespace fedsim::control_loading {
namespace {

constexpr double kH = 1e-3;

// Runs the axis for duration_s with a constant drive; returns the final position.
double hold(ControlAxis& axis, const AxisDrive& drive, double duration_s) {
  for (int n = 0; n < static_cast<int>(duration_s / kH); ++n) axis.substep(drive, kH);
  return axis.position_m();
}

struct RampPoint {
  double force_n;
  double position_m;
};

// Loads the control slowly (10 N/s, quasi-static) from 0 to max_force_n; the position at each
// of the given forces.
std::vector<RampPoint> ramp(const ControlAxisParameters& p, double qbar_pa, double max_force_n,
                            const std::vector<double>& at_forces_n) {
  ControlAxis axis(p, "pitch");
  AxisDrive drive;
  drive.gradient_npm = scheduled_gradient_npm(p, qbar_pa);
  std::vector<RampPoint> points;
  std::size_t next = 0;
  const double rate_nps = 10.0;
  for (int n = 0; n * kH * rate_nps <= max_force_n; ++n) {
    drive.pilot_force_n = n * kH * rate_nps;
    axis.substep(drive, kH);
    if (next < at_forces_n.size() && drive.pilot_force_n >= at_forces_n[next]) {
      points.push_back({drive.pilot_force_n, axis.position_m()});
      ++next;
    }
  }
  return points;
}

TEST(ControlAxis, GradientIsScheduledWithDynamicPressureBetweenFloorAndCeiling) {
  const ControlAxisParameters p = default_pitch_axis();
  EXPECT_DOUBLE_EQ(scheduled_gradient_npm(p, 0.0), 150.0);     // floor
  EXPECT_DOUBLE_EQ(scheduled_gradient_npm(p, 2000.0), 700.0);  // 0.35 m x 2000 Pa
  EXPECT_DOUBLE_EQ(scheduled_gradient_npm(p, 8000.0), 2800.0);
  EXPECT_DOUBLE_EQ(scheduled_gradient_npm(p, 50000.0), 4000.0);  // ceiling
}

TEST(ControlAxis, StaticForceDeflectionSlopeIsTheScheduledGradient) {
  const ControlAxisParameters p = default_pitch_axis();
  double slopes[2];
  int i = 0;
  for (double qbar : {2000.0, 8000.0}) {
    // 30 and 60 N: both above breakout + friction, both short of the soft stop at 90 % travel.
    const std::vector<RampPoint> pts = ramp(p, qbar, 100.0, {30.0, 60.0});
    ASSERT_EQ(pts.size(), 2u);
    slopes[i] = (pts[1].force_n - pts[0].force_n) / (pts[1].position_m - pts[0].position_m);
    const double k = scheduled_gradient_npm(p, qbar);
    EXPECT_NEAR(slopes[i], k, 0.01 * k) << qbar;
    // The force-deflection line meets x = 0 at breakout + friction (+ the ramp's viscous
    // 20 N s/m x 10/k m/s, under 0.3 N): F = F_bo + F_c + k x.
    const double intercept = pts[0].force_n - k * pts[0].position_m;
    EXPECT_NEAR(intercept, p.breakout_force_n + p.coulomb_friction_n, 0.5) << qbar;
    ++i;
  }
  // Negative control: the two dynamic pressures give gradients 4 times apart.
  EXPECT_NEAR(slopes[1] / slopes[0], 4.0, 0.05);
  std::printf("[figure] gradient at 2000 Pa: %.1f N/m (700), at 8000 Pa: %.1f N/m (2800)\n",
              slopes[0], slopes[1]);
}

TEST(ControlAxis, ForceBelowBreakoutMovesNothing) {
  const ControlAxisParameters p = default_pitch_axis();  // breakout 10 N, friction 4 N
  AxisDrive drive;
  drive.gradient_npm = scheduled_gradient_npm(p, 2000.0);
  ControlAxis axis(p, "pitch");
  drive.pilot_force_n = 0.9 * p.breakout_force_n;
  EXPECT_LT(std::abs(hold(axis, drive, 3.0)), p.breakout_width_m);  // < 0.5 mm: 0.5 % of travel
  drive.pilot_force_n = -0.9 * p.breakout_force_n;
  axis.reset(0.0, 0.0);
  EXPECT_LT(std::abs(hold(axis, drive, 3.0)), p.breakout_width_m);
  // Above breakout + friction it moves: to about (18.2 - 14)/700 = 6 mm.
  axis.reset(0.0, 0.0);
  drive.pilot_force_n = 1.3 * (p.breakout_force_n + p.coulomb_friction_n);
  EXPECT_GT(hold(axis, drive, 3.0), 0.004);
  // Negative control: without breakout and friction the 9 N moves it 9/700 = 12.9 mm.
  ControlAxisParameters free = p;
  free.breakout_force_n = 0.0;
  free.coulomb_friction_n = 0.0;
  ControlAxis loose(free, "pitch");
  drive.pilot_force_n = 0.9 * p.breakout_force_n;
  EXPECT_NEAR(hold(loose, drive, 5.0), 9.0 / 700.0, 1e-4);
}

// Upward zero crossings (interpolated) and the positive peaks of x(t) about 0.
struct Oscillation {
  std::vector<double> crossings_s;
  std::vector<double> peaks_m;
};
Oscillation release(const ControlAxisParameters& p, double qbar, double x0, double duration_s) {
  ControlAxis axis(p, "pitch");
  axis.reset(x0, 0.0);
  AxisDrive drive;
  drive.gradient_npm = scheduled_gradient_npm(p, qbar);
  Oscillation o;
  double previous = x0;
  double before_previous = x0;
  for (int n = 1; n <= static_cast<int>(duration_s / kH); ++n) {
    axis.substep(drive, kH);
    const double x = axis.position_m();
    if (previous < 0.0 && x >= 0.0)
      o.crossings_s.push_back((n - 1 + previous / (previous - x)) * kH);
    if (previous > x && previous > before_previous && previous > 0.0) o.peaks_m.push_back(previous);
    before_previous = previous;
    previous = x;
  }
  return o;
}

TEST(ControlAxis, FreeOscillationMatchesTheMassSpringDamper) {
  ControlAxisParameters p = default_pitch_axis();
  p.breakout_force_n = 0.0;
  p.coulomb_friction_n = 0.0;
  const double qbar = 6000.0;
  const double k = scheduled_gradient_npm(p, qbar);                               // 2100 N/m
  const double wn = std::sqrt(k / p.mass_kg);                                     // 26.46 rad/s
  const double zeta = p.viscous_damping_nspm / (2.0 * std::sqrt(k * p.mass_kg));  // 0.126
  const double wd = wn * std::sqrt(1.0 - zeta * zeta);
  const Oscillation o = release(p, qbar, 0.03, 1.5);
  ASSERT_GE(o.crossings_s.size(), 4u);
  ASSERT_GE(o.peaks_m.size(), 3u);
  const double period = (o.crossings_s[3] - o.crossings_s[0]) / 3.0;
  EXPECT_NEAR(2.0 * units::kPi / period, wd, 2e-3 * wd);
  const double decrement = std::log(o.peaks_m[0] / o.peaks_m[1]);
  const double measured_zeta =
      decrement / std::sqrt(4.0 * units::kPi * units::kPi + decrement * decrement);
  EXPECT_NEAR(measured_zeta, zeta, 0.01 * zeta);
  std::printf("[figure] free oscillation: wd %.3f rad/s (analytic %.3f), zeta %.4f (%.4f)\n",
              2.0 * units::kPi / period, wd, measured_zeta, zeta);
}

TEST(ControlAxis, CoulombFrictionDecaysLinearlyAndSticks) {
  ControlAxisParameters p = default_pitch_axis();
  p.breakout_force_n = 0.0;
  p.viscous_damping_nspm = 0.0;
  const double qbar = 6000.0;
  const double k = scheduled_gradient_npm(p, qbar);
  const Oscillation o = release(p, qbar, 0.05, 3.0);
  ASSERT_GE(o.peaks_m.size(), 2u);
  // Dry friction takes 4 F_c / k off the amplitude every cycle (Den Hartog).
  const double drop = 4.0 * p.coulomb_friction_n / k;
  EXPECT_NEAR(o.peaks_m[0] - o.peaks_m[1], drop, 0.02 * drop);
  ControlAxis axis(p, "pitch");
  axis.reset(0.05, 0.0);
  AxisDrive drive;
  drive.gradient_npm = k;
  hold(axis, drive, 5.0);
  EXPECT_EQ(axis.velocity_mps(), 0.0);
  EXPECT_TRUE(axis.stuck());
  EXPECT_LE(std::abs(axis.position_m()), p.coulomb_friction_n / k + 1e-12);
}

TEST(ControlAxis, HardStopHoldsWithSmallPenetrationAndThePhysicalStopBeyondTheMotorLimit) {
  const ControlAxisParameters p = default_pitch_axis();
  const double qbar = 6000.0;
  const double k = scheduled_gradient_npm(p, qbar);
  for (double sign : {1.0, -1.0}) {
    const double travel = sign > 0 ? p.positive_travel_m : p.negative_travel_m;
    ControlAxis axis(p, "pitch");
    AxisDrive drive;
    drive.gradient_npm = k;
    const double force = 550.0;  // below the 600 N motor limit
    drive.pilot_force_n = sign * force;
    hold(axis, drive, 3.0);
    // At the stop the pilot's force beyond the static feel at the travel goes into the hard-stop
    // spring in parallel with the gradient and the soft stop:
    // penetration = (F - F_feel(travel) -+ friction band) / (k_h + k_soft + k).
    const double feel_at_travel = k * travel + p.breakout_force_n +
                                  p.soft_stop_stiffness_npm * (1.0 - p.soft_stop_fraction) * travel;
    const double stiffness = p.hard_stop_stiffness_npm + p.soft_stop_stiffness_npm + k;
    const double penetration = sign * axis.position_m() - travel;
    const double expected = (force - feel_at_travel) / stiffness;
    EXPECT_GT(penetration, 0.0);
    EXPECT_NEAR(penetration, expected, p.coulomb_friction_n / stiffness + 1e-7);
    // Stated bound: at most motor_force_limit / k_h = 3 mm before the loader gives way.
    EXPECT_LT(penetration, p.motor_force_limit_n / p.hard_stop_stiffness_npm);
    EXPECT_NEAR(axis.loader_force_n(), -sign * force, p.coulomb_friction_n + 1e-6);
    EXPECT_FALSE(axis.on_mechanical_stop());
    // Beyond the motor limit the loader gives way and the physical stop holds the rest.
    drive.pilot_force_n = sign * 1000.0;
    hold(axis, drive, 1.0);
    EXPECT_TRUE(axis.on_mechanical_stop());
    EXPECT_NEAR(sign * axis.position_m(), travel + p.mechanical_stop_beyond_m, 1e-12);
    EXPECT_NEAR(std::abs(axis.loader_force_n()), p.motor_force_limit_n, 1e-9);
    EXPECT_NEAR(axis.mechanical_stop_force_n(), -sign * (1000.0 - p.motor_force_limit_n), 1e-6);
    std::printf("[figure] hard stop at %+.0f N: penetration %.3f mm (expected %.3f)\n",
                sign * force, penetration * 1e3, expected * 1e3);
  }
}

TEST(ControlAxis, EntersTheHardStopAtSpeedAndSettlesWithoutRinging) {
  // 250 N at rest (gradient floor 150 N/m) from 3 mm before the stop: in at about 0.5 m/s,
  // against the stiffest element. (A harder push at speed saturates the loader, and the
  // physical stop takes the impact, as the previous test shows.)
  const ControlAxisParameters p = default_pitch_axis();
  ControlAxis axis(p, "pitch");
  axis.reset(p.positive_travel_m - 0.003, 0.0);
  AxisDrive drive;
  drive.gradient_npm = scheduled_gradient_npm(p, 0.0);
  drive.pilot_force_n = 250.0;
  double entry_speed = 0.0;
  double deepest = 0.0;
  std::vector<double> late;
  for (int n = 1; n <= 2000; ++n) {
    axis.substep(drive, kH);
    if (axis.position_m() <= p.positive_travel_m) entry_speed = axis.velocity_mps();
    deepest = std::max(deepest, axis.position_m() - p.positive_travel_m);
    if (n > 1000) late.push_back(axis.position_m());
  }
  EXPECT_GT(entry_speed, 0.4);
  EXPECT_LT(deepest, p.mechanical_stop_beyond_m);  // the loader stopped it, not the physical stop
  EXPECT_FALSE(axis.on_mechanical_stop());
  const auto [lo, hi] = std::minmax_element(late.begin(), late.end());
  EXPECT_LT(*hi - *lo, 1e-9);  // at rest in the stop
  const double travel = p.positive_travel_m;
  const double feel_at_travel = drive.gradient_npm * travel + p.breakout_force_n +
                                p.soft_stop_stiffness_npm * (1.0 - p.soft_stop_fraction) * travel;
  const double stiffness =
      p.hard_stop_stiffness_npm + p.soft_stop_stiffness_npm + drive.gradient_npm;
  EXPECT_NEAR(axis.position_m() - travel, (250.0 - feel_at_travel) / stiffness,
              p.coulomb_friction_n / stiffness + 1e-7);
  std::printf("[figure] hard stop entered at %.2f m/s: deepest %.2f mm, rests at %.3f mm\n",
              entry_speed, deepest * 1e3, (axis.position_m() - p.positive_travel_m) * 1e3);
}

TEST(ControlAxis, BackdriveReachesTheCommandWithinItsForceLimit) {
  const ControlAxisParameters p = default_pitch_axis();
  const double target = 0.5 * p.positive_travel_m;
  for (double limit : {p.backdrive_force_limit_n, 60.0}) {
    ControlAxisParameters q = p;
    q.backdrive_force_limit_n = limit;
    ControlAxis axis(q, "pitch");
    AxisDrive drive;
    drive.gradient_npm = scheduled_gradient_npm(q, 6000.0);
    drive.backdrive_active = true;
    drive.backdrive_target_m = target;
    double max_servo = 0.0;
    double reached_s = -1.0;
    for (int n = 1; n <= 3000; ++n) {
      axis.substep(drive, kH);
      max_servo = std::max(max_servo, std::abs(axis.backdrive_force_n()));
      if (reached_s < 0.0 && std::abs(axis.position_m() - target) < 1e-3) reached_s = n * kH;
    }
    EXPECT_LE(max_servo, limit + 1e-9);
    if (limit == p.backdrive_force_limit_n) {
      EXPECT_GT(reached_s, 0.0);
      EXPECT_LT(reached_s, 1.0);
      // Dry friction leaves the servo a small error (stick-slip against the integral).
      EXPECT_NEAR(axis.position_m(), target, 1e-3);
      std::printf("[figure] back-drive to 50%% travel: within 1 mm after %.3f s, servo <= %.1f N\n",
                  reached_s, max_servo);
    } else {
      // Negative control: 60 N cannot hold 50 % travel against 2100 N/m x 0.05 m + 10 N.
      EXPECT_LT(axis.position_m(), target - 0.02);
      EXPECT_NEAR(max_servo, 60.0, 1e-9);
    }
  }
}

TEST(ControlAxis, TrimMovesTheDatumAtTheTrimRate) {
  const ControlAxisParameters p = default_pitch_axis();
  ControlAxis axis(p, "pitch");
  AxisDrive drive;
  drive.gradient_npm = scheduled_gradient_npm(p, 6000.0);
  drive.trim_target_m = p.trim_travel_m;  // trim input +1
  hold(axis, drive, 2.0);
  EXPECT_NEAR(axis.trim_m(), 2.0 * p.trim_rate_mps, 1e-9);  // still moving at 10 mm/s
  hold(axis, drive, 5.0);
  EXPECT_NEAR(axis.trim_m(), p.trim_travel_m, 1e-12);
  // The released control rests on the new datum, within the breakout width and friction band.
  EXPECT_NEAR(axis.position_m(), p.trim_travel_m,
              p.breakout_width_m + p.coulomb_friction_n / drive.gradient_npm);
}

TEST(ControlAxis, RejectsBadParametersNamingTheAxisAndField) {
  ControlAxisParameters p = default_roll_axis();
  p.gradient_max_npm = 10.0;  // below the floor
  try {
    ControlAxis axis(p, "roll");
    FAIL();
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("[roll]: gradient_max_npm"), std::string::npos);
  }
  p = default_yaw_axis();
  p.mass_kg = std::nan("");
  EXPECT_THROW(ControlAxis(p, "yaw"), std::invalid_argument);
  p = default_pitch_axis();
  p.backdrive_force_limit_n = 1000.0;  // above the motor limit
  EXPECT_THROW(ControlAxis(p, "pitch"), std::invalid_argument);
  p = default_pitch_axis();
  p.soft_stop_fraction = 1.0;
  EXPECT_THROW(ControlAxis(p, "pitch"), std::invalid_argument);
}

}  // namespace
}  // namespace fedsim::control_loading
