// Tests of the cubic spline against the seed's f1tab (Table 2.5 data tabulated in section 2.9).
#include "common/math/cubic_spline.hpp"
#include "common/math/test/seed_f1tab.hpp"

#include <gtest/gtest.h>

#include <cmath>

namespace fedsim {
namespace {

// Seed Table 2.5: dCL/dalpha component against Mach.
const std::vector<double> kMach = {0.0, 0.5, 0.6, 0.7, 0.8, 0.85, 0.875, 0.89, 0.91, 0.92, 0.95, 1.0};
const std::vector<double> kValue = {3.3, 3.4, 3.5, 3.65, 3.85, 4.15, 4.45, 4.65, 4.65, 4.5, 4.0, 3.65};

using testing::kF1tab;  // seed section 2.9, f1tab[]

TEST(CubicSpline, ReproducesTheSeedF1tab) {
  // The book's table was generated with Press et al.'s spline() with the end slopes set to the
  // end-segment chords (0.2 and -7.0); that reproduces all 101 values to their 4 decimals.
  const CubicSpline spline(kMach, kValue, SplineEnd::chord(), SplineEnd::chord());
  const std::vector<double> table = spline.tabulate(0.0, 0.01, 101);
  for (std::size_t i = 0; i < table.size(); ++i) {
    EXPECT_NEAR(table[i], kF1tab[i], 1e-4) << "M = " << 0.01 * i;
  }
}

TEST(CubicSpline, NaturalSplineAgreesWithF1tabAwayFromTheEnds) {
  // The natural spline (zero end curvature, seed 2.8) differs from f1tab only in the first and
  // last segments, where the end condition dominates (up to 0.026 at M = 0.98).
  const CubicSpline natural(kMach, kValue);
  for (int i = 50; i <= 92; ++i) EXPECT_NEAR(natural(0.01 * i), kF1tab[i], 1e-3) << i;
  EXPECT_GT(std::abs(natural(0.98) - kF1tab[98]), 0.02);
  EXPECT_NEAR(natural.second_derivatives().front(), 0.0, 1e-15);
  EXPECT_NEAR(natural.second_derivatives().back(), 0.0, 1e-15);
}

TEST(CubicSpline, PassesThroughTheKnotsWithContinuousSlope) {
  const CubicSpline spline(kMach, kValue);
  for (std::size_t i = 0; i < kMach.size(); ++i) EXPECT_NEAR(spline(kMach[i]), kValue[i], 1e-12);
  for (std::size_t i = 1; i + 1 < kMach.size(); ++i) {
    EXPECT_NEAR(spline.derivative(kMach[i] - 1e-9), spline.derivative(kMach[i] + 1e-9), 1e-5);
  }
}

TEST(CubicSpline, ReproducesACubicExactlyWithClampedEnds) {
  const auto f = [](double x) { return 2.0 - x + 0.5 * x * x - 0.25 * x * x * x; };
  const auto df = [](double x) { return -1.0 + x - 0.75 * x * x; };
  const std::vector<double> x = {-1.0, -0.2, 0.5, 1.5, 3.0};
  std::vector<double> y;
  for (double xi : x) y.push_back(f(xi));
  const CubicSpline spline(x, y, SplineEnd::clamped(df(-1.0)), SplineEnd::clamped(df(3.0)));
  for (double t = -1.0; t <= 3.0; t += 0.05) {
    EXPECT_NEAR(spline(t), f(t), 1e-12) << t;
    EXPECT_NEAR(spline.derivative(t), df(t), 1e-11) << t;
  }
}

TEST(CubicSpline, ClampsOutsideAndRejectsBadData) {
  const CubicSpline spline({0.0, 1.0, 2.0}, {1.0, 3.0, 2.0});
  EXPECT_DOUBLE_EQ(spline(-4.0), 1.0);
  EXPECT_DOUBLE_EQ(spline(9.0), 2.0);
  EXPECT_DOUBLE_EQ(spline.derivative(9.0), 0.0);
  EXPECT_THROW(CubicSpline({0.0}, {1.0}), std::invalid_argument);
  EXPECT_THROW(CubicSpline({0.0, 1.0}, {1.0}), std::invalid_argument);
  EXPECT_THROW(CubicSpline({1.0, 0.0}, {1.0, 2.0}), std::invalid_argument);
}

}  // namespace
}  // namespace fedsim
