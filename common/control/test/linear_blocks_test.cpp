// Frequency responses of the linear blocks against their continuous transfer functions, and
// DC gains, resets and copies. The reference is the analytic H(s), evaluated
//   - at the warped frequency w_a = c tan(w dt/2) of the block's bilinear map: the discrete
//     block must match it exactly (relative error 1e-8: the fit and round-off);
//   - at w itself where the map is exact (the pre-warp frequency: also 1e-8), and at low
//     frequency, w dt <= 0.1, where the map stretches w by at most (w dt)^2/12 = 8e-4: 2e-3.
#include <gtest/gtest.h>

#include <cmath>
#include <complex>
#include <vector>

#include "common/control/first_order_lag.hpp"
#include "common/control/integrator.hpp"
#include "common/control/lead_lag.hpp"
#include "common/control/second_order_filters.hpp"
#include "common/control/washout.hpp"
#include "common/control/test/frequency_response.hpp"
#include "common/units/units.hpp"

namespace fedsim::control {
namespace {

using test::Complex;
using test::measure_response;
using test::relative_error;
using test::warped_frequency_radps;

constexpr double kExact = 1e-8;        // against H(j w_a): the discrete response itself
constexpr double kLowFrequency = 2e-3; // against H(j w) for w dt <= 0.1
const Complex kJ{0.0, 1.0};

// Every block's response measured at the listed w against H(j c tan(w dt/2)).
template <class Block, class Continuous>
void expect_exact_map(Block block, Continuous h, double dt_s, double c_per_s, double settle_s,
                      const std::vector<double>& omegas_radps) {
  for (double w : omegas_radps) {
    Block fresh = block;
    const Complex measured =
        measure_response([&](double u) { return fresh.step(u); }, w, dt_s, settle_s);
    const Complex expected = h(kJ * warped_frequency_radps(w, dt_s, c_per_s));
    EXPECT_LT(relative_error(measured, expected), kExact)
        << "w = " << w << " rad/s: measured " << measured << ", expected " << expected;
  }
}

template <class Block, class Continuous>
void expect_close_at_low_frequency(Block block, Continuous h, double dt_s, double settle_s,
                                   const std::vector<double>& omegas_radps) {
  for (double w : omegas_radps) {
    ASSERT_LE(w * dt_s, 0.1);
    Block fresh = block;
    const Complex measured =
        measure_response([&](double u) { return fresh.step(u); }, w, dt_s, settle_s);
    EXPECT_LT(relative_error(measured, h(kJ * w)), kLowFrequency) << "w = " << w << " rad/s";
  }
}

// ---- First-order lag K/(tau s + 1) ----

TEST(FirstOrderLag, FollowsThePrewarpedMapAtEveryFrequencyUpToNyquist) {
  // Corner 100 rad/s at dt 0.01 s: 32% of Nyquist (314 rad/s), where pre-warping matters.
  const double tau = 0.01, dt = 0.01, k = 2.0;
  const auto h = [&](Complex s) { return k / (tau * s + 1.0); };
  expect_exact_map(FirstOrderLag(tau, dt, k), h, dt, test::prewarped_c(dt, 1.0 / tau), 1.0,
                   {5.0, 30.0, 100.0, 200.0, 300.0});
}

TEST(FirstOrderLag, IsExactAtTheCornerWhereThePlainTustinMapIsNot) {
  const double tau = 0.01, dt = 0.01;
  FirstOrderLag lag(tau, dt);
  const Complex at_corner =
      measure_response([&](double u) { return lag.step(u); }, 1.0 / tau, dt, 1.0);
  EXPECT_NEAR(std::abs(at_corner), 1.0 / std::sqrt(2.0), 1e-8);
  EXPECT_NEAR(std::arg(at_corner), -units::kPi / 4.0, 1e-8);
  // Negative control: the same lag through the plain map c = 2/T is 2.5 degrees off there.
  LinearSection<1> plain(bilinear(ContinuousTransferFunction<1>{{1.0, 0.0}, {1.0, tau}},
                                  tustin_constant_per_s(dt)));
  const Complex plain_at_corner =
      measure_response([&](double u) { return plain.step(u); }, 1.0 / tau, dt, 1.0);
  EXPECT_GT(std::abs(std::arg(plain_at_corner) + units::kPi / 4.0), 2.0 * units::kDegToRad);
}

TEST(FirstOrderLag, MatchesTheContinuousLagAtLowFrequency) {
  const double tau = 0.5, dt = 0.01, k = 1.5;
  expect_close_at_low_frequency(FirstOrderLag(tau, dt, k),
                                [&](Complex s) { return k / (tau * s + 1.0); }, dt, 20.0,
                                {0.1, 0.5, 2.0, 5.0, 10.0});
}

// ---- Lead-lag K (tau1 s + 1)/(tau2 s + 1) ----

TEST(LeadLag, FollowsThePrewarpedMapAndGivesItsLargestLeadAtTheGeometricMean) {
  const double tau1 = 0.05, tau2 = 0.01, dt = 0.01, k = 0.8;  // corners 20 and 100 rad/s
  const auto h = [&](Complex s) { return k * (tau1 * s + 1.0) / (tau2 * s + 1.0); };
  const LeadLag lead(tau1, tau2, dt, k);
  const double w_m = 1.0 / std::sqrt(tau1 * tau2);
  EXPECT_NEAR(lead.prewarp_frequency_radps(), w_m, 1e-12);
  expect_exact_map(lead, h, dt, test::prewarped_c(dt, w_m), 1.0, {2.0, 20.0, w_m, 100.0, 280.0});
  // The classical maximum lead: sin(phi_max) = (tau1 - tau2)/(tau1 + tau2), at w_m exactly.
  LeadLag fresh = lead;
  const Complex at_mean = measure_response([&](double u) { return fresh.step(u); }, w_m, dt, 1.0);
  EXPECT_NEAR(std::arg(at_mean), std::asin((tau1 - tau2) / (tau1 + tau2)), 1e-8);
}

TEST(LeadLag, MatchesTheContinuousLeadLagAtLowFrequency) {
  const double tau1 = 1.0, tau2 = 0.2, dt = 0.01;
  expect_close_at_low_frequency(LeadLag(tau1, tau2, dt),
                                [&](Complex s) { return (tau1 * s + 1.0) / (tau2 * s + 1.0); }, dt,
                                10.0, {0.2, 1.0, 5.0, 10.0});
}

// ---- Washout K tau s/(tau s + 1) ----

TEST(Washout, FollowsThePrewarpedMapAndIsExactAtTheCorner) {
  const double tau = 0.02, dt = 0.01, k = 1.0;
  const auto h = [&](Complex s) { return k * tau * s / (tau * s + 1.0); };
  expect_exact_map(Washout(tau, dt, k), h, dt, test::prewarped_c(dt, 1.0 / tau), 1.0,
                   {1.0, 10.0, 50.0, 150.0, 300.0});
  Washout washout(tau, dt, k);
  const Complex at_corner =
      measure_response([&](double u) { return washout.step(u); }, 1.0 / tau, dt, 1.0);
  EXPECT_NEAR(std::abs(at_corner), 1.0 / std::sqrt(2.0), 1e-8);
  EXPECT_NEAR(std::arg(at_corner), units::kPi / 4.0, 1e-8);
}

TEST(Washout, MatchesTheContinuousWashoutAtLowFrequency) {
  const double tau = 2.0, dt = 0.01, k = 3.0;
  expect_close_at_low_frequency(Washout(tau, dt, k),
                                [&](Complex s) { return k * tau * s / (tau * s + 1.0); }, dt, 80.0,
                                {0.05, 0.5, 2.0, 10.0});
}

// ---- Second-order filters on s^2 + 2 zeta wn s + wn^2 ----

Complex second_order_denominator(Complex s, double wn, double zeta) {
  return s * s + 2.0 * zeta * wn * s + wn * wn;
}

TEST(SecondOrderLowPass, FollowsThePrewarpedMapAndResonatesAtWnExactly) {
  const double wn = 100.0, zeta = 0.3, dt = 0.01;  // wn at 32% of Nyquist
  const auto h = [&](Complex s) { return wn * wn / second_order_denominator(s, wn, zeta); };
  const SecondOrderLowPass filter(wn, zeta, dt);
  expect_exact_map(filter, h, dt, test::prewarped_c(dt, wn), 2.0,
                   {5.0, 50.0, 90.0, wn, 120.0, 250.0, 300.0});
  // At wn the continuous low-pass has gain 1/(2 zeta) and phase -90 degrees.
  SecondOrderLowPass fresh = filter;
  const Complex at_wn = measure_response([&](double u) { return fresh.step(u); }, wn, dt, 2.0);
  EXPECT_NEAR(std::abs(at_wn), 1.0 / (2.0 * zeta), 1e-8);
  EXPECT_NEAR(std::arg(at_wn), -units::kHalfPi, 1e-8);
  // Negative control: plain Tustin moves the -90 degree point away from wn (to 1.093 wn here:
  // 16 degrees off at wn).
  ContinuousTransferFunction<2> continuous{{wn * wn, 0.0, 0.0}, {wn * wn, 2.0 * zeta * wn, 1.0}};
  LinearSection<2> plain(bilinear(continuous, tustin_constant_per_s(dt)));
  const Complex plain_at_wn =
      measure_response([&](double u) { return plain.step(u); }, wn, dt, 2.0);
  EXPECT_GT(std::abs(std::arg(plain_at_wn) + units::kHalfPi), 10.0 * units::kDegToRad);
}

TEST(SecondOrderLowPass, MatchesTheContinuousFilterAtLowFrequency) {
  const double wn = 10.0, zeta = 0.5, dt = 0.005;
  expect_close_at_low_frequency(
      SecondOrderLowPass(wn, zeta, dt),
      [&](Complex s) { return wn * wn / second_order_denominator(s, wn, zeta); }, dt, 8.0,
      {1.0, 5.0, 10.0, 20.0});
}

TEST(SecondOrderHighPass, FollowsThePrewarpedMap) {
  const double wn = 60.0, zeta = 0.7, dt = 0.01;
  const auto h = [&](Complex s) { return s * s / second_order_denominator(s, wn, zeta); };
  expect_exact_map(SecondOrderHighPass(wn, zeta, dt), h, dt, test::prewarped_c(dt, wn), 1.0,
                   {2.0, 30.0, wn, 150.0, 300.0});
}

TEST(SecondOrderHighPass, MatchesTheContinuousFilterAtLowFrequency) {
  // A motion-cueing translational washout: wn 2 rad/s, zeta 1, at 100 Hz.
  const double wn = 2.0, zeta = 1.0, dt = 0.01;
  expect_close_at_low_frequency(
      SecondOrderHighPass(wn, zeta, dt),
      [&](Complex s) { return s * s / second_order_denominator(s, wn, zeta); }, dt, 20.0,
      {0.2, 1.0, 2.0, 10.0});
}

TEST(BandPass, HasUnitGainAndZeroPhaseAtItsCentreAndFollowsThePrewarpedMap) {
  const double wn = 80.0, zeta = 0.2, dt = 0.01;
  const auto h = [&](Complex s) {
    return 2.0 * zeta * wn * s / second_order_denominator(s, wn, zeta);
  };
  const BandPass filter(wn, zeta, dt);
  expect_exact_map(filter, h, dt, test::prewarped_c(dt, wn), 2.0, {5.0, 60.0, wn, 100.0, 250.0});
  BandPass fresh = filter;
  const Complex at_wn = measure_response([&](double u) { return fresh.step(u); }, wn, dt, 2.0);
  EXPECT_NEAR(std::abs(at_wn), 1.0, 1e-8);
  EXPECT_NEAR(std::arg(at_wn), 0.0, 1e-8);
}

TEST(Notch, RemovesItsCentreFrequencyExactlyWherePlainTustinDoesNot) {
  const double wn = 120.0, zeta = 0.1, dt = 0.01;
  const auto h = [&](Complex s) {
    return (s * s + wn * wn) / second_order_denominator(s, wn, zeta);
  };
  const Notch notch(wn, zeta, dt);
  expect_exact_map(notch, h, dt, test::prewarped_c(dt, wn), 3.0, {10.0, 100.0, 140.0, 280.0});
  Notch fresh = notch;
  const Complex at_wn = measure_response([&](double u) { return fresh.step(u); }, wn, dt, 3.0);
  EXPECT_LT(std::abs(at_wn), 1e-8);
  // Negative control: without pre-warping the notch sits at (2/T) atan(wn T/2) = 108 rad/s and
  // passes 80% of the amplitude at 120 rad/s.
  ContinuousTransferFunction<2> continuous{{wn * wn, 0.0, 1.0}, {wn * wn, 2.0 * zeta * wn, 1.0}};
  LinearSection<2> plain(bilinear(continuous, tustin_constant_per_s(dt)));
  const Complex plain_at_wn =
      measure_response([&](double u) { return plain.step(u); }, wn, dt, 3.0);
  EXPECT_GT(std::abs(plain_at_wn), 0.5);
}

// ---- Integrator K/s: plain Tustin (the trapezoidal rule) ----

TEST(Integrator, FollowsTheTrapezoidalMap) {
  const double k = 3.0, dt = 0.01;
  const auto h = [&](Complex s) { return k / s; };
  expect_exact_map(Integrator(k, dt), h, dt, test::plain_c(dt), 0.0, {1.0, 10.0, 100.0, 300.0});
  expect_close_at_low_frequency(Integrator(k, dt), h, dt, 0.0, {0.5, 2.0, 10.0});
}

// ---- DC gains, reset without transient, copies ----

template <class Block>
double settle_on(Block& block, double u, int steps) {
  double y = 0.0;
  for (int n = 0; n < steps; ++n) y = block.step(u);
  return y;
}

TEST(LinearBlocks, DcGainsAreThoseOfTheContinuousForms) {
  const double dt = 0.01;
  FirstOrderLag lag(0.2, dt, 2.5);
  LeadLag lead(0.3, 0.05, dt, -1.5);
  Washout washout(0.5, dt, 4.0);
  SecondOrderLowPass low(20.0, 0.6, dt);
  SecondOrderHighPass high(20.0, 0.6, dt);
  BandPass band(20.0, 0.6, dt);
  Notch notch(20.0, 0.6, dt);
  EXPECT_NEAR(settle_on(lag, 2.0, 2000), 5.0, 1e-12);
  EXPECT_NEAR(settle_on(lead, 2.0, 2000), -3.0, 1e-12);
  EXPECT_NEAR(settle_on(washout, 2.0, 5000), 0.0, 1e-12);
  EXPECT_NEAR(settle_on(low, 2.0, 2000), 2.0, 1e-12);
  EXPECT_NEAR(settle_on(high, 2.0, 2000), 0.0, 1e-12);
  EXPECT_NEAR(settle_on(band, 2.0, 2000), 0.0, 1e-12);
  EXPECT_NEAR(settle_on(notch, 2.0, 2000), 2.0, 1e-12);
}

template <class Block>
double largest_departure(Block& block, double u, double y0, int steps) {
  double worst = 0.0;
  for (int n = 0; n < steps; ++n) worst = std::max(worst, std::abs(block.step(u) - y0));
  return worst;
}

TEST(LinearBlocks, ResetPutsTheBlockInSteadyStateAtThatOutput) {
  const double dt = 0.01;
  FirstOrderLag lag(0.2, dt, 2.5);
  lag.reset(5.0);
  EXPECT_EQ(lag.output(), 5.0);
  EXPECT_LT(largest_departure(lag, 2.0, 5.0, 300), 1e-12);  // held input y/K = 2
  LeadLag lead(0.3, 0.05, dt, -1.5);
  lead.reset(-3.0);
  EXPECT_LT(largest_departure(lead, 2.0, -3.0, 300), 1e-12);
  SecondOrderLowPass low(20.0, 0.3, dt);
  low.reset(7.0);
  EXPECT_LT(largest_departure(low, 7.0, 7.0, 300), 1e-12);
  Notch notch(20.0, 0.3, dt);
  notch.reset(-1.0);
  EXPECT_LT(largest_departure(notch, -1.0, -1.0, 300), 1e-12);
  Washout washout(0.5, dt);
  washout.reset_to_input(9.0);
  EXPECT_EQ(washout.output(), 0.0);
  EXPECT_LT(largest_departure(washout, 9.0, 0.0, 300), 1e-12);
  SecondOrderHighPass high(5.0, 0.7, dt);
  high.reset_to_input(9.0);
  EXPECT_LT(largest_departure(high, 9.0, 0.0, 300), 1e-12);
  BandPass band(5.0, 0.7, dt);
  band.reset_to_input(9.0);
  EXPECT_LT(largest_departure(band, 9.0, 0.0, 300), 1e-12);
  // Negative control: the same held inputs from rest give a transient.
  FirstOrderLag lag_at_rest(0.2, dt, 2.5);
  EXPECT_GT(largest_departure(lag_at_rest, 2.0, 5.0, 300), 1.0);
  Washout washout_at_rest(0.5, dt);
  EXPECT_GT(largest_departure(washout_at_rest, 9.0, 0.0, 300), 5.0);
}

TEST(LinearBlocks, CopiesAreIndependentValues) {
  SecondOrderLowPass original(15.0, 0.4, 0.01);
  for (int n = 0; n < 37; ++n) original.step(std::sin(0.1 * n));
  SecondOrderLowPass copy = original;
  for (int n = 0; n < 50; ++n) {
    EXPECT_EQ(copy.step(1.0), original.step(1.0));
  }
  copy.step(100.0);  // moves the copy only
  EXPECT_NE(copy.output(), original.output());
}

}  // namespace
}  // namespace fedsim::control
