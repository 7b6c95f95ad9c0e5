// Step responses of the linear blocks against the analytic continuous solutions.
//
// A unit step applied at sample 0 reaches a bilinear (trapezoidal) block as a ramp from 0 at
// sample -1 to 1 at sample 0: to first order a step at t = -dt/2. The discrete responses are
// compared with the continuous ones at t + dt/2; what remains is O((dt/tau)^2) with tau the
// fastest time constant (1/wn for a second-order block): about 0.12 (dt/tau)^2 of the step for a
// lag, so the tolerance is 0.25 (dt/tau)^2 (5e-5 to 1e-4 here). They are also compared with
// the textbook figures (63.2% at one time constant, the overshoot exp(-pi zeta/sqrt(1-zeta^2)))
// within the half-sample lead that shift implies.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <vector>

#include "common/control/first_order_lag.hpp"
#include "common/control/lead_lag.hpp"
#include "common/control/second_order_filters.hpp"
#include "common/control/washout.hpp"
#include "common/units/units.hpp"

namespace fedsim::control {
namespace {

// The tolerance on a unit step response, tau the fastest time constant [s] (see above).
double step_tolerance(double dt_s, double tau_s) { return 0.25 * (dt_s / tau_s) * (dt_s / tau_s); }

template <class Block>
std::vector<double> unit_step_response(Block block, int steps) {
  std::vector<double> y(steps);
  for (int n = 0; n < steps; ++n) y[n] = block.step(1.0);
  return y;
}

// The first time (linear interpolation between samples) at which y reaches level.
double crossing_time_s(const std::vector<double>& y, double level, double dt_s) {
  for (std::size_t n = 1; n < y.size(); ++n) {
    if (y[n - 1] < level && y[n] >= level) {
      return dt_s * ((n - 1) + (level - y[n - 1]) / (y[n] - y[n - 1]));
    }
  }
  return -1.0;
}

TEST(StepResponse, FirstOrderLagRises632PercentInOneTimeConstant) {
  const double tau = 0.5, dt = 0.01, k = 2.0;
  const std::vector<double> y = unit_step_response(FirstOrderLag(tau, dt, k), 400);
  for (int n = 0; n < 400; ++n) {
    const double t = n * dt + 0.5 * dt;
    ASSERT_NEAR(y[n], k * (1.0 - std::exp(-t / tau)), step_tolerance(dt, tau) * k) << "n = " << n;
  }
  // 1 - 1/e of the final value at tau, half a sample early (the step's trapezoidal start).
  EXPECT_NEAR(crossing_time_s(y, k * (1.0 - std::exp(-1.0)), dt), tau - 0.5 * dt, 1e-4);
  EXPECT_NEAR(y[static_cast<int>(tau / dt)], k * 0.632, k * (0.5 * dt / tau) * 0.37 + 1e-3);
}

TEST(StepResponse, WashoutDecaysWithItsTimeConstant) {
  const double tau = 0.8, dt = 0.01, k = 1.5;
  const std::vector<double> y = unit_step_response(Washout(tau, dt, k), 500);
  for (int n = 0; n < 500; ++n) {
    const double t = n * dt + 0.5 * dt;
    ASSERT_NEAR(y[n], k * std::exp(-t / tau), step_tolerance(dt, tau) * k) << "n = " << n;
  }
  // Falls to 1/e of its initial jump at tau (less half a sample).
  std::vector<double> falling(y.size());
  std::transform(y.begin(), y.end(), falling.begin(), [](double v) { return -v; });
  EXPECT_NEAR(crossing_time_s(falling, -k * std::exp(-1.0), dt), tau - 0.5 * dt, 1e-4);
}

TEST(StepResponse, LeadLagJumpsToTheRatioOfItsTimeConstantsAndSettlesOnItsLagTimeConstant) {
  const double tau1 = 0.3, tau2 = 0.1, dt = 0.005;
  const std::vector<double> y = unit_step_response(LeadLag(tau1, tau2, dt), 400);
  for (int n = 0; n < 400; ++n) {
    const double t = n * dt + 0.5 * dt;
    ASSERT_NEAR(y[n], 1.0 + (tau1 / tau2 - 1.0) * std::exp(-t / tau2),
                step_tolerance(dt, tau2) * tau1 / tau2) << "n = " << n;
  }
}

// The underdamped second-order step response 1 - e^{-zeta wn t}(cos wd t + zeta/sqrt(1-zeta^2)
// sin wd t), wd = wn sqrt(1 - zeta^2).
double second_order_step(double t, double wn, double zeta) {
  const double root = std::sqrt(1.0 - zeta * zeta);
  const double wd = wn * root;
  return 1.0 - std::exp(-zeta * wn * t) * (std::cos(wd * t) + zeta / root * std::sin(wd * t));
}

class SecondOrderStep : public ::testing::TestWithParam<double> {};

TEST_P(SecondOrderStep, OvershootsByTheClassicalFigureAtTheClassicalTime) {
  const double zeta = GetParam(), wn = units::kTwoPi, dt = 0.002;  // 1 Hz at 500 Hz
  const std::vector<double> y = unit_step_response(SecondOrderLowPass(wn, zeta, dt), 3000);
  for (int n = 0; n < 3000; ++n) {
    ASSERT_NEAR(y[n], second_order_step(n * dt + 0.5 * dt, wn, zeta), step_tolerance(dt, 1.0 / wn))
        << "n = " << n;
  }
  const auto peak = std::max_element(y.begin(), y.end());
  const double overshoot = *peak - 1.0;
  EXPECT_NEAR(overshoot, std::exp(-units::kPi * zeta / std::sqrt(1.0 - zeta * zeta)), 5e-4);
  const double peak_time_s = (peak - y.begin()) * dt + 0.5 * dt;
  EXPECT_NEAR(peak_time_s, units::kPi / (wn * std::sqrt(1.0 - zeta * zeta)), dt);
}

INSTANTIATE_TEST_SUITE_P(DampingRatios, SecondOrderStep, ::testing::Values(0.2, 0.5, 0.7));

TEST(StepResponse, CriticallyDampedLowPassDoesNotOvershoot) {
  const double wn = 10.0, dt = 0.005;
  const std::vector<double> y = unit_step_response(SecondOrderLowPass(wn, 1.0, dt), 2000);
  for (int n = 0; n < 2000; ++n) {
    const double t = n * dt + 0.5 * dt;
    ASSERT_NEAR(y[n], 1.0 - std::exp(-wn * t) * (1.0 + wn * t), step_tolerance(dt, 1.0 / wn))
        << "n = " << n;
  }
  EXPECT_LE(*std::max_element(y.begin(), y.end()), 1.0 + 1e-12);
}

TEST(StepResponse, SecondOrderHighPassStartsAtOneAndWashesOut) {
  // H = (s^2/wn^2) x low-pass: its step response is the low-pass step response's second
  // derivative over wn^2, e^{-zeta wn t}(cos wd t - zeta/sqrt(1 - zeta^2) sin wd t).
  const double wn = 2.0, zeta = 0.5, dt = 0.005;
  const std::vector<double> y = unit_step_response(SecondOrderHighPass(wn, zeta, dt), 2000);
  const double root = std::sqrt(1.0 - zeta * zeta);
  for (int n = 0; n < 2000; ++n) {
    const double t = n * dt + 0.5 * dt;
    const double expected = std::exp(-zeta * wn * t) *
                            (std::cos(wn * root * t) - zeta / root * std::sin(wn * root * t));
    ASSERT_NEAR(y[n], expected, step_tolerance(dt, 1.0 / wn)) << "n = " << n;
  }
}

}  // namespace
}  // namespace fedsim::control
