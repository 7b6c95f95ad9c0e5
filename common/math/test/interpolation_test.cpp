#include "common/math/interpolation.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

namespace fedsim {
namespace {

TEST(Table1D, InterpolatesBetweenNonUniformBreakpoints) {
  // Seed Table 2.5 (dCL/dalpha against Mach).
  const Table1D table({0.0, 0.5, 0.6, 0.7, 0.8, 0.85, 0.875, 0.89, 0.91, 0.92, 0.95, 1.0},
                      {3.3, 3.4, 3.5, 3.65, 3.85, 4.15, 4.45, 4.65, 4.65, 4.5, 4.0, 3.65});
  EXPECT_DOUBLE_EQ(table(0.0), 3.3);
  EXPECT_DOUBLE_EQ(table(0.85), 4.15);
  EXPECT_NEAR(table(0.25), 3.35, 1e-12);
  EXPECT_NEAR(table(0.8625), 4.30, 1e-12);
  EXPECT_NEAR(table(0.935), 4.25, 1e-12);
}

TEST(Table1D, ClampsOutsideTheBreakpointsAndSurvivesNaN) {
  const Table1D table({0.0, 1.0}, {2.0, 4.0});
  EXPECT_DOUBLE_EQ(table(-5.0), 2.0);
  EXPECT_DOUBLE_EQ(table(5.0), 4.0);
  EXPECT_TRUE(std::isfinite(table(std::numeric_limits<double>::quiet_NaN())));
}

TEST(Table1D, RejectsBadBreakpoints) {
  EXPECT_THROW(Table1D({0.0, 0.0}, {1.0, 2.0}), std::invalid_argument);
  EXPECT_THROW(Table1D({0.0, 1.0}, {1.0}), std::invalid_argument);
}

// Seed Example 2.4 CT table: rows are blade angle (deg), columns advance ratio J.
Table2D seed_ct_table() {
  std::vector<double> beta{0, 5, 10, 15, 20, 25, 30, 35, 40};
  std::vector<double> j{0.0, 0.2, 0.4, 0.6, 0.8, 1.0, 1.2, 1.4, 1.6, 1.8, 2.0, 2.2};
  std::vector<double> ct(36, 0.0);
  const std::vector<double> rest{
      0.092, 0.084, 0.065, 0.037, 0.007, -0.022, -0.050, -0.080, -0.108, -0.137, -0.167, -0.196,
      0.099, 0.096, 0.089, 0.064, 0.036, 0.006,  -0.023, -0.054, -0.084, -0.115, -0.144, -0.175,
      0.118, 0.114, 0.110, 0.095, 0.071, 0.043,  0.013,  -0.017, -0.045, -0.073, -0.102, -0.131,
      0.115, 0.110, 0.106, 0.100, 0.101, 0.080,  0.053,  0.024,  -0.007, -0.038, -0.068, -0.098,
      0.139, 0.132, 0.126, 0.119, 0.113, 0.108,  0.089,  0.065,  0.038,  0.010,  -0.020, -0.048,
      0.141, 0.135, 0.128, 0.123, 0.120, 0.114,  0.112,  0.101,  0.080,  0.057,  0.030,  0.005};
  ct.insert(ct.end(), rest.begin(), rest.end());
  return Table2D(beta, j, ct);
}

TEST(Table2D, ReproducesSeedCtTableAtNodesAndBetween) {
  const Table2D ct = seed_ct_table();
  EXPECT_DOUBLE_EQ(ct(15.0, 0.0), 0.092);
  EXPECT_DOUBLE_EQ(ct(30.0, 1.2), 0.053);
  EXPECT_DOUBLE_EQ(ct(40.0, 2.2), 0.005);
  // Midway in both directions: mean of the four corners.
  EXPECT_NEAR(ct(22.5, 0.5), (0.089 + 0.064 + 0.110 + 0.095) / 4.0, 1e-12);
  // Clamped beyond both edges.
  EXPECT_DOUBLE_EQ(ct(90.0, 9.0), 0.005);
  EXPECT_DOUBLE_EQ(ct(-10.0, -1.0), 0.0);
}

TEST(Table3D, IsTrilinear) {
  // w = 1 + 2 p + 3 r + 4 c is reproduced exactly by trilinear interpolation.
  std::vector<double> p{0, 1}, r{0, 2, 3}, c{-1, 1};
  std::vector<double> v;
  for (double pp : p)
    for (double rr : r)
      for (double cc : c) v.push_back(1 + 2 * pp + 3 * rr + 4 * cc);
  const Table3D t(p, r, c, v);
  EXPECT_NEAR(t(0.25, 2.5, 0.1), 1 + 0.5 + 7.5 + 0.4, 1e-12);
}

}  // namespace
}  // namespace fedsim
