// Tests of the cubic spline against the seed's f1tab (Table 2.5 data tabulated in section 2.9).
#include "flight/model/math/cubic_spline.hpp"

#include <gtest/gtest.h>

#include <cmath>

namespace fedsim::flight {
namespace {

// Seed Table 2.5: dCL/dalpha component against Mach.
const std::vector<double> kMach = {0.0, 0.5, 0.6, 0.7, 0.8, 0.85, 0.875, 0.89, 0.91, 0.92, 0.95, 1.0};
const std::vector<double> kValue = {3.3, 3.4, 3.5, 3.65, 3.85, 4.15, 4.45, 4.65, 4.65, 4.5, 4.0, 3.65};

// Seed section 2.9, f1tab[]: the spline of Table 2.5 tabulated at M = 0, 0.01, ..., 1.0.
constexpr double kF1tab[] = {
    3.3000, 3.3019, 3.3036, 3.3051, 3.3065, 3.3076, 3.3087, 3.3096, 3.3104, 3.3111, 3.3116,
    3.3121, 3.3126, 3.3129, 3.3132, 3.3135, 3.3138, 3.3141, 3.3143, 3.3146, 3.3149, 3.3153,
    3.3157, 3.3161, 3.3167, 3.3173, 3.3181, 3.3189, 3.3199, 3.3211, 3.3224, 3.3238, 3.3255,
    3.3273, 3.3293, 3.3316, 3.3341, 3.3368, 3.3398, 3.3430, 3.3465, 3.3504, 3.3545, 3.3589,
    3.3637, 3.3688, 3.3743, 3.3801, 3.3864, 3.3930, 3.4000, 3.4074, 3.4153, 3.4237, 3.4327,
    3.4422, 3.4524, 3.4632, 3.4747, 3.4870, 3.5000, 3.5138, 3.5284, 3.5434, 3.5588, 3.5744,
    3.5900, 3.6056, 3.6208, 3.6357, 3.6500, 3.6637, 3.6772, 3.6912, 3.7062, 3.7228, 3.7416,
    3.7631, 3.7880, 3.8167, 3.8500, 3.8887, 3.9353, 3.9925, 4.0631, 4.1500, 4.2554, 4.3802,
    4.5233, 4.6500, 4.7010, 4.6500, 4.5000, 4.3211, 4.1476, 4.0000, 3.8930, 3.8184, 3.7622,
    3.7107, 3.650};

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
}  // namespace fedsim::flight
