// The one bilinear transform against closed forms derived independently:
//  - first order: K/(tau s + 1) with constant c gives b0 = b1 = K/(c tau + 1),
//    a1 = (1 - c tau)/(1 + c tau) (Franklin, Powell & Workman, section 6.3.2);
//  - second order: the biquads of R. Bristow-Johnson's "Cookbook formulae for audio EQ biquad
//    filter coefficients", which are the bilinear transform pre-warped at w0 = wn T of the
//    prototypes 1/(s^2 + s/Q + 1) etc. with Q = 1/(2 zeta):
//      alpha = sin(w0)/(2Q); a = {1 + alpha, -2 cos w0, 1 - alpha} (then divided by a0);
//      low-pass b = {(1 - cos w0)/2, 1 - cos w0, (1 - cos w0)/2}; high-pass
//      b = {(1 + cos w0)/2, -(1 + cos w0), (1 + cos w0)/2}; band-pass (0 dB peak)
//      b = {alpha, 0, -alpha}; notch b = {1, -2 cos w0, 1}.
#include "common/control/bilinear.hpp"

#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <stdexcept>

#include "common/control/second_order_filters.hpp"

namespace fedsim::control {
namespace {

TEST(Bilinear, TustinConstants) {
  EXPECT_DOUBLE_EQ(tustin_constant_per_s(0.01), 200.0);
  // Pre-warped at w_p: c tan(w_p T/2) = w_p; c = (2/T)(1 - (w_p T)^2/12 + ...) -> 2/T.
  const double c = prewarped_tustin_constant_per_s(0.01, 100.0);
  EXPECT_NEAR(c * std::tan(0.5), 100.0, 1e-12);
  EXPECT_NEAR(prewarped_tustin_constant_per_s(0.01, 1e-3) / 200.0, 1.0 - 1e-10 / 12.0, 1e-15);
  EXPECT_NEAR(prewarped_tustin_constant_per_s(0.01, 50.0) / 200.0, 1.0 - 0.25 / 12.0, 2e-4);
}

TEST(Bilinear, FirstOrderLagMatchesTheClosedForm) {
  const double k = 2.5, tau = 0.3, c = 180.0;
  const DiscreteTransferFunction<1> d =
      bilinear(ContinuousTransferFunction<1>{{k, 0.0}, {1.0, tau}}, c);
  EXPECT_DOUBLE_EQ(d.a[0], 1.0);
  EXPECT_NEAR(d.b[0], k / (c * tau + 1.0), 1e-15);
  EXPECT_NEAR(d.b[1], k / (c * tau + 1.0), 1e-15);
  EXPECT_NEAR(d.a[1], (1.0 - c * tau) / (1.0 + c * tau), 1e-15);
}

struct Cookbook {
  std::array<double, 3> b;
  std::array<double, 3> a;
};

Cookbook normalised(std::array<double, 3> b, std::array<double, 3> a) {
  for (double& v : b) v /= a[0];
  const double a0 = a[0];
  for (double& v : a) v /= a0;
  return {b, a};
}

template <class Filter>
void expect_cookbook(const Filter& filter, const Cookbook& expected) {
  const DiscreteTransferFunction<2>& d = filter.coefficients();
  for (int i = 0; i < 3; ++i) {
    EXPECT_NEAR(d.b[i], expected.b[i], 1e-13) << "b" << i;
    EXPECT_NEAR(d.a[i], expected.a[i], 1e-13) << "a" << i;
  }
}

TEST(Bilinear, SecondOrderFiltersAreTheCookbookBiquads) {
  const double wn = 150.0, zeta = 0.35, dt = 0.01;
  const double w0 = wn * dt, q = 1.0 / (2.0 * zeta);
  const double alpha = std::sin(w0) / (2.0 * q), cw = std::cos(w0);
  const std::array<double, 3> a{1.0 + alpha, -2.0 * cw, 1.0 - alpha};
  expect_cookbook(SecondOrderLowPass(wn, zeta, dt),
                  normalised({(1.0 - cw) / 2.0, 1.0 - cw, (1.0 - cw) / 2.0}, a));
  expect_cookbook(SecondOrderHighPass(wn, zeta, dt),
                  normalised({(1.0 + cw) / 2.0, -(1.0 + cw), (1.0 + cw) / 2.0}, a));
  expect_cookbook(BandPass(wn, zeta, dt), normalised({alpha, 0.0, -alpha}, a));
  expect_cookbook(Notch(wn, zeta, dt), normalised({1.0, -2.0 * cw, 1.0}, a));
}

TEST(Bilinear, KeepsTheDcGain) {
  // z = 1 is s = 0 under every c: sum b / sum a = H(0) (to round-off: the sums cancel terms of
  // size c^2, hence 1e-9 at c = 5000).
  const ContinuousTransferFunction<2> h{{3.0, 1.0, 0.5}, {2.0, 0.7, 0.1}};
  for (double c : {10.0, 200.0, 5000.0}) {
    const DiscreteTransferFunction<2> d = bilinear(h, c);
    EXPECT_NEAR((d.b[0] + d.b[1] + d.b[2]) / (d.a[0] + d.a[1] + d.a[2]), 1.5, 1e-9) << c;
  }
}

TEST(Bilinear, RejectsADenominatorThatVanishesAtC) {
  // s - c has its root at s = c: no proper discrete form.
  EXPECT_THROW(bilinear(ContinuousTransferFunction<1>{{1.0, 0.0}, {-100.0, 1.0}}, 100.0),
               std::invalid_argument);
}

}  // namespace
}  // namespace fedsim::control
