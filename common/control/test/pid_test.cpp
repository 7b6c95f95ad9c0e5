// PID: the parallel form's frequency response against Kp + Ki/s + Kd s/(tau_f s + 1), the
// filtered derivative's step response, anti-windup (conditional integration and back-
// calculation, each against the windup of the same PID with an external saturation), and
// bumpless engagement.
#include "common/control/pid.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <complex>
#include <limits>
#include <stdexcept>
#include <string>

#include "common/control/limiter.hpp"
#include "common/control/test/frequency_response.hpp"

namespace fedsim::control {
namespace {

using test::Complex;

const Complex kJ{0.0, 1.0};

PidParameters pid_parameters(double kp, double ki, double kd, double tau_f) {
  PidParameters p;
  p.proportional_gain = kp;
  p.integral_gain_per_s = ki;
  p.derivative_gain_s = kd;
  p.derivative_filter_time_constant_s = tau_f;
  return p;
}

// p with its output limited to [-limit, +limit] (limit = infinity: unlimited).
PidParameters with_output_limit(PidParameters p, double limit) {
  p.output_min = -limit;
  p.output_max = limit;
  return p;
}

constexpr double kUnlimited = std::numeric_limits<double>::infinity();

TEST(Pid, FrequencyResponseIsTheParallelFormUnderEachTermsMap) {
  // The integral uses the plain map (2/T) tan(w T/2), the derivative the map pre-warped at
  // 1/tau_f: exact (1e-8) under those maps, and within 2e-3 of H(jw) for w dt <= 0.1. (The
  // roll-off is at 10 rad/s, w_p dt = 0.1: pre-warping there shrinks the low-frequency axis by
  // only (w_p dt)^2/12 = 8e-4; see README.md.)
  const double kp = 1.2, ki = 0.8, kd = 0.05, tau_f = 0.1, dt = 0.01;
  const PidParameters p = pid_parameters(kp, ki, kd, tau_f);
  const auto continuous = [&](Complex s_i, Complex s_d) {
    return kp + ki / s_i + kd * s_d / (tau_f * s_d + 1.0);
  };
  for (double w : {0.5, 5.0, 50.0, 200.0}) {
    Pid pid(p, dt);
    const Complex measured =
        test::measure_response([&](double e) { return pid.step(e); }, w, dt, 4.0);
    const double w_i = test::warped_frequency_radps(w, dt, test::plain_c(dt));
    const double w_d = test::warped_frequency_radps(w, dt, test::prewarped_c(dt, 1.0 / tau_f));
    const Complex exact = continuous(kJ * w_i, kJ * w_d);
    EXPECT_LT(test::relative_error(measured, exact), 1e-8) << "w = " << w;
    if (w * dt <= 0.1) {
      EXPECT_LT(test::relative_error(measured, continuous(kJ * w, kJ * w)), 2e-3) << "w = " << w;
    }
  }
}

TEST(Pid, FilteredDerivativeOfAStepDecaysWithTheFilterTimeConstant) {
  // Kd s/(tau_f s + 1) on a unit step: (Kd/tau_f) e^{-t/tau_f} (at t + dt/2, see
  // step_response_test.cpp, and its tolerance 0.25 (dt/tau_f)^2 of the jump); no P, no I.
  const double kd = 0.3, tau_f = 0.1, dt = 0.005;
  Pid pid(pid_parameters(0.0, 0.0, kd, tau_f), dt);
  for (int n = 0; n < 300; ++n) {
    const double t = n * dt + 0.5 * dt;
    const double tolerance = 0.25 * (dt / tau_f) * (dt / tau_f) * kd / tau_f;
    ASSERT_NEAR(pid.step(1.0), kd / tau_f * std::exp(-t / tau_f), tolerance) << n;
  }
}

TEST(Pid, ProportionalOnlyIsAGain) {
  Pid pid(pid_parameters(-2.5, 0.0, 0.0, 0.0), 0.01);
  EXPECT_EQ(pid.step(0.4), -1.0);
  EXPECT_EQ(pid.step(-2.0), 5.0);
  EXPECT_EQ(pid.integral(), 0.0);
  EXPECT_EQ(pid.derivative(), 0.0);
}

// A PI on an integrating plant x' = u (u limited to +-1), the setpoint 10 from x = 0: the
// closed loop s^2 + Kp s + Ki (Kp 1, Ki 0.5: zeta 0.71) overshoots 4.3% unlimited; saturated for
// the first 9 s, an unprotected integral winds up. Returns the largest overshoot of x past 10.
double overshoot_of_saturated_loop(const PidParameters& p, bool external_saturation) {
  const double dt = 0.01, setpoint = 10.0;
  Pid pid(p, dt);
  Limiter actuator(-1.0, 1.0);
  double x = 0.0, highest = 0.0;
  for (int n = 0; n < 6000; ++n) {
    double u = pid.step(setpoint - x);
    if (external_saturation) u = actuator.step(u);
    x += u * dt;
    highest = std::max(highest, x);
  }
  return highest - setpoint;
}

PidParameters saturated_pi(AntiWindup method) {
  PidParameters p = with_output_limit(pid_parameters(1.0, 0.5, 0.0, 0.0), 1.0);
  p.anti_windup = method;
  p.tracking_time_constant_s = 1.0;
  return p;
}

TEST(Pid, AntiWindupKeepsTheSaturatedLoopFromOvershooting) {
  const double conditional =
      overshoot_of_saturated_loop(saturated_pi(AntiWindup::kConditionalIntegration), false);
  const double back_calculation =
      overshoot_of_saturated_loop(saturated_pi(AntiWindup::kBackCalculation), false);
  // Negative control: the same PI unlimited inside, the actuator saturating outside.
  const PidParameters unprotected =
      with_output_limit(saturated_pi(AntiWindup::kConditionalIntegration), kUnlimited);
  const double windup = overshoot_of_saturated_loop(unprotected, true);
  EXPECT_LT(conditional, 1.0);
  EXPECT_LT(back_calculation, 1.0);
  EXPECT_GT(windup, 5.0);
  RecordProperty("overshoot_conditional", std::to_string(conditional));
  RecordProperty("overshoot_back_calculation", std::to_string(back_calculation));
  RecordProperty("overshoot_windup", std::to_string(windup));
}

TEST(Pid, ConditionalIntegrationLeavesTheLimitAtOnceWhenTheErrorReverses) {
  const double dt = 0.01;
  PidParameters p = with_output_limit(pid_parameters(0.1, 1.0, 0.0, 0.0), 1.0);
  Pid pid(p, dt);
  for (int n = 0; n < 1000; ++n) pid.step(5.0);  // 10 s: unprotected, I would reach 50
  EXPECT_EQ(pid.output(), 1.0);
  EXPECT_LE(pid.integral(), 1.0);
  EXPECT_LT(pid.step(-0.5), 1.0);  // the first step after the reversal
  // Negative control: unlimited inside, saturated outside, it stays at the limit for 40 s.
  const PidParameters unprotected = with_output_limit(p, kUnlimited);
  Pid wound(unprotected, dt);
  Limiter saturation(-1.0, 1.0);
  for (int n = 0; n < 1000; ++n) saturation.step(wound.step(5.0));
  for (int n = 0; n < 4000; ++n) ASSERT_EQ(saturation.step(wound.step(-0.5)), 1.0) << n;
}

TEST(Pid, BackCalculationBleedsTheIntegralToTheLimitWithTheTrackingTimeConstant) {
  const double dt = 0.01, tracking_s = 0.5;
  PidParameters p = with_output_limit(pid_parameters(0.0, 1.0, 0.0, 0.0), 1.0);
  p.anti_windup = AntiWindup::kBackCalculation;
  p.tracking_time_constant_s = tracking_s;
  Pid pid(p, dt);
  for (int n = 0; n < 2000; ++n) pid.step(2.0);
  // Steady state of I' = Ki e + (sat(I) - I)/T_t: I = 1 + Ki e T_t = 2.
  EXPECT_NEAR(pid.integral(), 1.0 + 1.0 * 2.0 * tracking_s, 1e-6);
  EXPECT_EQ(pid.output(), 1.0);
}

TEST(Pid, EngageIsBumpless) {
  const double dt = 0.01;
  PidParameters p = with_output_limit(pid_parameters(2.0, 0.5, 0.1, 0.05), 10.0);
  Pid pid(p, dt);
  for (int n = 0; n < 200; ++n) pid.step(std::sin(0.05 * n));  // some history to overwrite
  const double error = 0.3, held_output = 4.0;
  pid.engage(error, held_output);
  EXPECT_EQ(pid.output(), held_output);
  // The next step differs only by the integral's own change Ki e dt.
  const double first = pid.step(error);
  EXPECT_NEAR(first, held_output + 0.5 * error * dt, 1e-12);
  // And a slowly moving error moves the output smoothly from there.
  double previous = first;
  for (int n = 1; n < 100; ++n) {
    const double y = pid.step(error + 0.001 * n);
    ASSERT_LT(std::abs(y - previous), 0.01) << n;
    previous = y;
  }
  // Negative control: a plain reset restarts from P + D = 0.6 + 0.55 (the derivative kick), a
  // step of 2.85 from the held 4.0.
  Pid restarted(p, dt);
  restarted.reset();
  EXPECT_GT(std::abs(restarted.step(error) - held_output), 2.0);
}

TEST(Pid, EngageOutsideTheLimitsIsRejected) {
  PidParameters p = with_output_limit(pid_parameters(1.0, 1.0, 0.0, 0.0), 1.0);
  Pid pid(p, 0.01);
  EXPECT_THROW(pid.engage(0.0, 1.5), std::invalid_argument);
  EXPECT_THROW(pid.engage(std::nan(""), 0.5), std::invalid_argument);
}

}  // namespace
}  // namespace fedsim::control
