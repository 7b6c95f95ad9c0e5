// The control-loading system: the inner-loop rate and its stability at the stiffest stop,
// fading in, the stick shaker (only above its angle of attack, with hysteresis), the safety
// cut-offs (watchdog, invalid inputs, overspeed, instructor), the force limit, the simulated
// pilot, the felt force.
#include "control_loading/model/control_loading.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <complex>
#include <cstdio>
#include <stdexcept>
#include <vector>

namespace fedsim::control_loading {
namespace {

constexpr double kFrame = 1.0 / 60.0;

ControlLoadingInputs cruise(double qbar = 6000.0, double alpha = 0.05) {
  ControlLoadingInputs in;
  in.qbar_pa = qbar;
  in.alpha_rad = alpha;
  return in;
}

ControlLoading active_loader(const ControlLoadingParameters& p = {}) {
  ControlLoading loader(p);
  EXPECT_EQ(loader.status(), LoaderStatus::kSafe);
  EXPECT_TRUE(loader.engage());
  for (int n = 0; n < 60 && loader.status() != LoaderStatus::kActive; ++n) {
    loader.step(cruise(), kFrame);
  }
  EXPECT_EQ(loader.status(), LoaderStatus::kActive);
  return loader;
}

const AxisOutputs& pitch(const ControlLoadingOutputs& out) {
  return out.axes[static_cast<int>(Axis::kPitch)];
}

TEST(ControlLoading, InnerLoopRunsAtLeastAtOneKilohertz) {
  ControlLoading loader{ControlLoadingParameters{}};
  EXPECT_EQ(loader.substeps_for(1.0 / 60.0), 17);  // 1020 Hz
  EXPECT_EQ(loader.substeps_for(1.0 / 50.0), 20);  // 1000 Hz
  EXPECT_EQ(loader.substeps_for(0.1), 100);
  EXPECT_EQ(loader.step(cruise(), kFrame).substeps, 17);
  EXPECT_GT(loader.max_stable_substep_s(), 1e-3);
}

// The semi-implicit Euler update of m x'' = -k x - c v over h: [v; x] <- A [v; x].
double spectral_radius(double k, double c, double m, double h) {
  const double a11 = 1.0 - c * h / m;
  const double a12 = -k * h / m;
  const double a21 = h * a11;
  const double a22 = 1.0 + h * a12;
  const double tr = a11 + a22;
  const double det = a11 * a22 - a12 * a21;
  const std::complex<double> root = std::sqrt(std::complex<double>(tr * tr / 4.0 - det, 0.0));
  return std::max(std::abs(tr / 2.0 + root), std::abs(tr / 2.0 - root));
}

TEST(ControlLoading, TheStiffestStopIsStableAtTheChosenSubstep) {
  ControlLoading loader{ControlLoadingParameters{}};
  const double h = kFrame / loader.substeps_for(kFrame);
  for (int i = 0; i < kAxisCount; ++i) {
    const ControlAxis& axis = loader.axis(static_cast<Axis>(i));
    const double k =
        axis.stiffest_spring_npm() + ControlLoadingParameters{}.pilot.hand_stiffness_npm;
    const double c =
        axis.largest_damping_nspm() + ControlLoadingParameters{}.pilot.hand_damping_nspm;
    const double m = axis.parameters().mass_kg;
    EXPECT_LT(spectral_radius(k, c, m, h), 1.0) << i;
    EXPECT_LT(spectral_radius(k, c, m, loader.max_stable_substep_s()), 1.0) << i;
    // Negative control: a sub-step past the Jury bound (w h)^2 + 2 c h/m = 4 diverges.
    const double a = k / m;
    const double b = 2.0 * c / m;
    const double beyond = (-b + std::sqrt(b * b + 4.0 * a * 4.5)) / (2.0 * a);
    EXPECT_GT(spectral_radius(k, c, m, beyond), 1.0) << i;
  }
}

TEST(ControlLoading, ForcesFadeInAfterEngage) {
  ControlLoading loader{ControlLoadingParameters{}};
  ControlLoadingInputs in = cruise();
  in.axes[0].pilot_force_n = 60.0;
  for (int n = 0; n < 30; ++n) loader.step(in, kFrame);  // safe: pushed freely to the stop
  EXPECT_TRUE(pitch(loader.outputs()).in_hard_stop || pitch(loader.outputs()).on_mechanical_stop);
  in.axes[0].pilot_force_n = 0.0;
  const ControlAxis& column = loader.axis(Axis::kPitch);
  const double centring_n = std::abs(column.static_feel_force_n(
      column.position_m(), 0.0, scheduled_gradient_npm(column.parameters(), 6000.0)));
  ASSERT_TRUE(loader.engage());
  EXPECT_FALSE(loader.engage());
  double previous_force = pitch(loader.outputs()).feel_force_n;
  double largest_jump = 0.0;
  int frames = 0;
  while (loader.status() != LoaderStatus::kActive) {
    const double force = pitch(loader.step(in, kFrame)).feel_force_n;
    largest_jump = std::max(largest_jump, std::abs(force - previous_force));
    previous_force = force;
    ++frames;
  }
  EXPECT_NEAR(frames * kFrame, 0.5, kFrame);
  // The centring force at the physical stop (over 1000 N unlimited; the loader gives 600 N at
  // most) builds up over 0.5 s instead of at once: no frame-to-frame step above a tenth of it.
  EXPECT_GT(centring_n, 600.0);
  EXPECT_LT(largest_jump, 0.1 * centring_n);
}

TEST(ControlLoading, StickShakerOnlyAboveItsAngleOfAttack) {
  ControlLoading loader = active_loader();
  auto shake_run = [&](double alpha, double seconds) {
    std::vector<double> force;
    for (int n = 0; n < static_cast<int>(seconds / kFrame); ++n) {
      const ControlLoadingOutputs& out = loader.step(cruise(6000.0, alpha), kFrame);
      force.push_back(pitch(out).feel_force_n);
    }
    return force;
  };
  shake_run(0.20, 2.0);  // settle
  const std::vector<double> quiet = shake_run(0.20, 1.0);
  EXPECT_FALSE(loader.outputs().stick_shaker);
  const auto [lo, hi] = std::minmax_element(quiet.begin(), quiet.end());
  EXPECT_LT(*hi - *lo, 1e-9);
  // Above 0.24 rad it shakes: the 15 Hz force, sampled here per sub-step through the axis.
  shake_run(0.25, 0.1);
  EXPECT_TRUE(loader.outputs().stick_shaker);
  std::vector<double> column;
  int crossings = 0;
  double previous = 0.0;
  ControlLoadingInputs in = cruise(6000.0, 0.25);
  for (int n = 0; n < 120; ++n) {  // 2 s
    const double x = pitch(loader.step(in, kFrame)).position_m;
    column.push_back(x);
  }
  const double mean = [&] {
    double s = 0.0;
    for (double x : column) s += x;
    return s / column.size();
  }();
  for (double x : column) {
    if ((previous < 0.0) != (x - mean < 0.0)) ++crossings;
    previous = x - mean;
  }
  const auto [clo, chi] = std::minmax_element(column.begin(), column.end());
  EXPECT_GT(*chi - *clo, 1e-4);  // the column visibly shakes
  EXPECT_GT(crossings, 10);
  EXPECT_EQ(loader.axis(Axis::kRoll).position_m(), 0.0);  // only pitch has a shaker
  // Hysteresis: still on at 0.235 rad, off at 0.225.
  shake_run(0.235, 0.1);
  EXPECT_TRUE(loader.outputs().stick_shaker);
  shake_run(0.225, 0.1);
  EXPECT_FALSE(loader.outputs().stick_shaker);
}

TEST(ControlLoading, TheAircraftsWarningAngleMovesTheShaker) {
  ControlLoading loader = active_loader();
  auto at = [&](double alpha, double warning) {
    ControlLoadingInputs in = cruise(6000.0, alpha);
    in.shaker_alpha_rad = warning;
    for (int n = 0; n < 10; ++n) loader.step(in, kFrame);
    return loader.outputs().stick_shaker;
  };
  EXPECT_FALSE(at(0.20, std::nan("")));  // the parameters' 0.24 rad
  EXPECT_TRUE(at(0.20, 0.18));           // flaps down: a lower warning angle
  EXPECT_FALSE(at(0.16, 0.18));          // below it less the hysteresis (0.01 rad)
  EXPECT_FALSE(at(0.20, 2.0));           // beyond pi/2: refused, the parameters' angle
  EXPECT_TRUE(at(0.25, 2.0));
}

TEST(ControlLoading, ShakerFrequencyIsFifteenHertz) {
  // Frames of 1 ms (one sub-step each) sample the shaking column finely enough to count it.
  ControlLoading loader = active_loader();
  ControlLoadingInputs in = cruise(6000.0, 0.3);
  loader.step(in, kFrame);
  std::vector<double> x;
  for (int n = 0; n < 1000; ++n) x.push_back(pitch(loader.step(in, 1e-3)).position_m);
  // Count mean crossings of the position over 1 s: 2 per period.
  double mean = 0.0;
  for (double v : x) mean += v / x.size();
  int crossings = 0;
  for (std::size_t i = 1; i < x.size(); ++i) {
    if ((x[i - 1] - mean < 0.0) != (x[i] - mean < 0.0)) ++crossings;
  }
  EXPECT_NEAR(crossings / 2.0, 15.0, 1.0);
}

TEST(ControlLoading, WatchdogCutsOffWithinTheFrameWhenFlightDataStop) {
  ControlLoading loader = active_loader();
  ControlLoadingInputs in = cruise();
  in.axes[0].pilot_force_n = 80.0;
  for (int n = 0; n < 60; ++n) loader.step(in, kFrame);
  const double held = pitch(loader.outputs()).position_m;  // deflected against the spring
  EXPECT_GT(held, 0.02);
  in.axes[0].pilot_force_n = 0.0;  // pilot lets go ...
  in.flight_data_age_s = 0.15;     // ... as the flight data stop
  const ControlLoadingOutputs& out = loader.step(in, kFrame);
  EXPECT_EQ(out.status, LoaderStatus::kSafe);
  EXPECT_NE(loader.cut_off_reason().find("watchdog"), std::string::npos);
  // Safe: no spring pulls the released column back, only the damping acts on it.
  for (int n = 0; n < 60; ++n) loader.step(in, kFrame);
  EXPECT_NEAR(pitch(loader.outputs()).position_m, held, 0.01);
  EXPECT_LT(std::abs(pitch(loader.outputs()).feel_force_n), 1.0);
  // Negative control: fresh data keep it active and the spring recentres the column.
  ControlLoading other = active_loader();
  in.flight_data_age_s = 0.05;
  in.axes[0].pilot_force_n = 80.0;
  for (int n = 0; n < 60; ++n) other.step(in, kFrame);
  in.axes[0].pilot_force_n = 0.0;
  for (int n = 0; n < 61; ++n) other.step(in, kFrame);
  EXPECT_EQ(other.status(), LoaderStatus::kActive);
  EXPECT_LT(std::abs(pitch(other.outputs()).position_m), 0.01);
}

TEST(ControlLoading, InvalidInputsCutOffNamingTheField) {
  struct Case {
    const char* field;
    void (*spoil)(ControlLoadingInputs&);
  };
  const Case cases[] = {
      {"qbar_pa", [](ControlLoadingInputs& in) { in.qbar_pa = std::nan(""); }},
      {"qbar_pa", [](ControlLoadingInputs& in) { in.qbar_pa = -5.0; }},
      {"alpha_rad", [](ControlLoadingInputs& in) { in.alpha_rad = INFINITY; }},
      {"roll pilot_force_n",
       [](ControlLoadingInputs& in) { in.axes[1].pilot_force_n = std::nan(""); }},
      {"yaw trim_norm", [](ControlLoadingInputs& in) { in.axes[2].trim_norm = 1.5; }},
      {"pitch backdrive_target_norm",
       [](ControlLoadingInputs& in) { in.axes[0].backdrive_target_norm = std::nan(""); }},
      {"pitch pilot_force_n", [](ControlLoadingInputs& in) { in.axes[0].pilot_force_n = 5000.0; }},
  };
  for (const Case& c : cases) {
    ControlLoading loader = active_loader();
    ControlLoadingInputs in = cruise();
    c.spoil(in);
    EXPECT_EQ(loader.step(in, kFrame).status, LoaderStatus::kSafe) << c.field;
    EXPECT_NE(loader.cut_off_reason().find(c.field), std::string::npos)
        << c.field << ": " << loader.cut_off_reason();
    for (const AxisOutputs& a : loader.outputs().axes) {
      EXPECT_TRUE(std::isfinite(a.position_m)) << c.field;
    }
    // It stays safe until engaged again, then fades back in.
    loader.step(cruise(), kFrame);
    EXPECT_EQ(loader.status(), LoaderStatus::kSafe);
    EXPECT_TRUE(loader.engage());
    EXPECT_EQ(loader.step(cruise(), kFrame).status, LoaderStatus::kFadingIn);
  }
  ControlLoading loader{ControlLoadingParameters{}};
  EXPECT_THROW(loader.step(cruise(), 0.0), std::invalid_argument);
}

TEST(ControlLoading, OverspeedAndInstructorCutOff) {
  ControlLoadingParameters p;
  p.axes[2].velocity_trip_mps = 0.3;
  ControlLoading loader = active_loader(p);
  ControlLoadingInputs in = cruise();
  in.axes[2].pilot_force_n = 900.0;  // kicks the pedal
  for (int n = 0; n < 30 && loader.status() == LoaderStatus::kActive; ++n) loader.step(in, kFrame);
  EXPECT_EQ(loader.status(), LoaderStatus::kSafe);
  EXPECT_EQ(loader.cut_off_reason(), "overspeed on yaw");
  ControlLoading second = active_loader();
  second.cut_off("instructor: control loading off");
  EXPECT_EQ(second.status(), LoaderStatus::kSafe);
  EXPECT_EQ(second.cut_off_reason(), "instructor: control loading off");
}

TEST(ControlLoading, LoaderForceNeverExceedsItsLimit) {
  ControlLoading loader = active_loader();
  ControlLoadingInputs in = cruise(20000.0);
  double largest = 0.0;
  // The pilot leans on the column and wheel up to 1400 N over 2 s, then lets go.
  for (int n = 0; n <= 180; ++n) {
    const double force = 1400.0 * std::min(1.0, n / 120.0);
    in.axes[0].pilot_force_n = force;
    in.axes[1].pilot_force_n = -force;
    const ControlLoadingOutputs& out = loader.step(in, kFrame);
    largest = std::max(largest, out.axes[0].max_loader_force_n);
    EXPECT_LE(out.axes[1].max_loader_force_n, default_roll_axis().motor_force_limit_n + 1e-9);
  }
  EXPECT_EQ(loader.status(), LoaderStatus::kActive);
  EXPECT_NEAR(largest, default_pitch_axis().motor_force_limit_n, 1e-9);  // reached, not passed
  EXPECT_TRUE(pitch(loader.outputs()).on_mechanical_stop);
  EXPECT_TRUE(loader.outputs().axes[1].on_mechanical_stop);
}

TEST(ControlLoading, FeltForceBalancesThePilotAtRest) {
  ControlLoading loader = active_loader();
  ControlLoadingInputs in = cruise();
  in.axes[1].pilot_force_n = -50.0;
  for (int n = 0; n < 120; ++n) loader.step(in, kFrame);
  const AxisOutputs& roll = loader.outputs().axes[1];
  EXPECT_NEAR(roll.feel_force_n, 50.0, 1e-9);
  EXPECT_LT(roll.position_norm, 0.0);
  EXPECT_NEAR(roll.gradient_npm, 900.0, 1e-9);  // 0.15 m x 6000 Pa
}

TEST(ControlLoading, SimulatedPilotPutsTheControlWhereItWants) {
  ControlLoading loader = active_loader();
  ControlLoadingInputs in = cruise();
  in.pilot_source = PilotSource::kSimulatedPilot;
  in.axes[0].pilot_target_norm = 0.5;
  in.axes[2].pilot_target_norm = -0.3;
  for (int n = 0; n < 60; ++n) loader.step(in, kFrame);
  EXPECT_NEAR(pitch(loader.outputs()).position_norm, 0.5, 0.02);
  EXPECT_NEAR(loader.outputs().axes[2].position_norm, -0.3, 0.02);
  EXPECT_GT(pitch(loader.outputs()).pilot_force_n, 100.0);  // it pushes against 2100 N/m
}

TEST(ControlLoading, BackdriveThroughTheLoader) {
  ControlLoading loader = active_loader();
  ControlLoadingInputs in = cruise();
  in.axes[0].backdrive_active = true;
  in.axes[0].backdrive_target_norm = -0.4;  // 40 % aft = -0.06 m
  double largest = 0.0;
  for (int n = 0; n < 60; ++n)
    largest = std::max(largest, pitch(loader.step(in, kFrame)).max_backdrive_force_n);
  EXPECT_NEAR(pitch(loader.outputs()).position_norm, -0.4, 0.01);
  EXPECT_LE(largest, default_pitch_axis().backdrive_force_limit_n + 1e-9);
}

TEST(ControlLoading, RejectsBadParameters) {
  ControlLoadingParameters p;
  p.inner_rate_hz = 500.0;
  EXPECT_THROW(ControlLoading{p}, std::invalid_argument);
  p = {};
  p.shaker_alpha_rad = -0.1;
  EXPECT_THROW(ControlLoading{p}, std::invalid_argument);
  p = {};
  p.watchdog_timeout_s = std::nan("");
  EXPECT_THROW(ControlLoading{p}, std::invalid_argument);
  p = {};
  p.axes[1].hard_stop_stiffness_npm = 0.0;
  EXPECT_THROW(ControlLoading{p}, std::invalid_argument);
}

}  // namespace
}  // namespace fedsim::control_loading
