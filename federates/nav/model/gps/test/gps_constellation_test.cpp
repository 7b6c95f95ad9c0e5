// The nominal constellation: radius, period, inclination, plane spacing, nodal regression, and
// visibility from the ground over a day.
#include "federates/nav/model/gps/gps_constellation.hpp"
#include "federates/nav/model/gps/gps_constellation_data.hpp"
#include "federates/nav/model/gps/pseudorange_model.hpp"

#include "common/geodesy/wgs84.hpp"
#include "common/units/units.hpp"

#include <gtest/gtest.h>

#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>
#include <limits>
#include <set>
#include <stdexcept>

namespace fedsim::nav {
namespace {

constexpr double kDeg = units::kDegToRad;

TEST(GpsConstellation, BaselineHas24SlotsInSixPlanes) {
  const GpsConstellation c = GpsConstellation::baseline_24();
  ASSERT_EQ(c.size(), 24u);
  std::set<long> raan_deg;
  for (std::size_t k = 0; k < c.size(); ++k) {
    raan_deg.insert(std::lround(c.orbit(k).raan_at_epoch_rad / kDeg));
  }
  // Six planes, 60 deg apart: 33, 93, 153, 213, 273, 333 deg.
  EXPECT_EQ(raan_deg, (std::set<long>{33, 93, 153, 213, 273, 333}));
}

TEST(GpsConstellation, SatellitesAreAtTheRightRadiusInclinationAndPeriod) {
  const GpsConstellation c = GpsConstellation::baseline_24(/*j2_nodal_regression=*/false);
  for (std::size_t k = 0; k < c.size(); ++k) {
    const double period_s = c.orbital_period_s(k);
    // 11 h 58 min (half a sidereal day, 43082 s) within 30 s.
    EXPECT_NEAR(period_s, 11.0 * 3600.0 + 58.0 * 60.0, 30.0);
    for (double t : {0.0, 1234.5, 86400.0 * 3.3}) {
      EXPECT_NEAR(c.position_eci_m(k, t).norm(), 26559.7e3, 1e-6);
      EXPECT_NEAR(c.position_ecef_m(k, t).norm(), 26559.7e3, 1e-6);
      // Inclination: the orbit normal r x v has z-component cos(55 deg).
      const Eigen::Vector3d r = c.position_eci_m(k, t);
      const Eigen::Vector3d r_later = c.position_eci_m(k, t + 1.0);
      EXPECT_NEAR(r.cross(r_later).normalized().z(), std::cos(55.0 * kDeg), 1e-9);
    }
    // Back where it was after one period (inertially), not after 11 h 50 min.
    const Eigen::Vector3d start = c.position_eci_m(k, 1000.0);
    EXPECT_LT((c.position_eci_m(k, 1000.0 + period_s) - start).norm(), 1e-3);
    EXPECT_GT((c.position_eci_m(k, 1000.0 + period_s - 480.0) - start).norm(), 1.0e6);
  }
  // The standard's slot A1 at the epoch: argument of latitude 268.126 deg, RAAN 272.847 deg.
  const Eigen::Vector3d a1 = c.position_eci_m(0, 0.0);
  const double u = 268.126 * kDeg;
  const double raan = 272.847 * kDeg;
  const double i = 55.0 * kDeg;
  const Eigen::Vector3d expected =
      26559.7e3 * Eigen::Vector3d(std::cos(raan) * std::cos(u) - std::sin(raan) * std::sin(u) * std::cos(i),
                                  std::sin(raan) * std::cos(u) + std::cos(raan) * std::sin(u) * std::cos(i),
                                  std::sin(u) * std::sin(i));
  EXPECT_LT((a1 - expected).norm(), 1e-6);
}

TEST(GpsConstellation, NodalRegressionMatchesTheNominalAlmanac) {
  // The SPS Performance Standard (3rd ed., 2001, Table A-2-1) lists the nominal constellation's
  // rate of right ascension as -4.4874e-7 (deg/s, -0.0388 deg/day).
  const GpsConstellation c = GpsConstellation::baseline_24();
  EXPECT_NEAR(c.raan_rate_radps(0) / (-4.4874e-7 * kDeg), 1.0, 0.01);
  EXPECT_EQ(GpsConstellation::baseline_24(false).raan_rate_radps(0), 0.0);
}

TEST(GpsConstellation, GroundTrackFollowsTheEarthsRotation) {
  // At the epoch the Greenwich hour angle is 18 h 36 min 14.4 s = 279.06 deg; one sidereal day
  // later (2 pi / omega_e) it is the same.
  EXPECT_NEAR(GpsConstellation::greenwich_hour_angle_rad(0.0) / kDeg, 279.06, 1e-9);
  const double sidereal_day_s = units::kTwoPi / wgs84::kEarthRateRadps;
  EXPECT_NEAR(GpsConstellation::greenwich_hour_angle_rad(sidereal_day_s) / kDeg, 279.06, 1e-6);
  // ECEF = R3(theta_G) ECI: the z component is unchanged, the longitude is shifted by -theta_G.
  const GpsConstellation c = GpsConstellation::baseline_24();
  const double t = 5000.0;
  const Eigen::Vector3d eci = c.position_eci_m(3, t);
  const Eigen::Vector3d ecef = c.position_ecef_m(3, t);
  EXPECT_NEAR(ecef.z(), eci.z(), 1e-6);
  const double shift = std::remainder(std::atan2(eci.y(), eci.x()) - std::atan2(ecef.y(), ecef.x()) -
                                          GpsConstellation::greenwich_hour_angle_rad(t),
                                      units::kTwoPi);
  EXPECT_NEAR(shift, 0.0, 1e-12);
}

struct VisibilityStatistics {
  int min = std::numeric_limits<int>::max();
  int max = 0;
  double mean = 0.0;
};

VisibilityStatistics visibility_over_a_day(double lat_deg, double mask_deg) {
  const GpsConstellation c = GpsConstellation::baseline_24();
  PseudorangeConfig config;
  config.mask_angle_rad = mask_deg * kDeg;
  const PseudorangeModel model(config);
  const Eigen::Vector3d receiver = Wgs84::ecef_from_geodetic({lat_deg * kDeg, 7.0 * kDeg, 0.0});
  VisibilityStatistics s;
  int samples = 0;
  for (double t = 0.0; t < 86400.0; t += 120.0) {
    const int n = static_cast<int>(model.visible(c, t, receiver).size());
    s.min = std::min(s.min, n);
    s.max = std::max(s.max, n);
    s.mean += n;
    ++samples;
  }
  s.mean /= samples;
  return s;
}

TEST(GpsConstellation, SixToTwelveSatellitesAreVisibleTypically) {
  // Over a day (every 2 min) at a 5 deg mask the 24-slot constellation shows 6 to 11
  // satellites (measured: 0 deg N 7-10, mean 8.7; 45 deg N 6-10, mean 7.6; 60 deg N 6-11,
  // mean 8.5); with a 15 deg mask 4-9, means 5.9-6.8.
  for (double lat_deg : {0.0, 45.0, 60.0}) {
    const VisibilityStatistics s = visibility_over_a_day(lat_deg, 5.0);
    EXPECT_GE(s.min, 6) << lat_deg;
    EXPECT_LE(s.max, 12) << lat_deg;
    EXPECT_GE(s.mean, 7.0) << lat_deg;
    EXPECT_LE(s.mean, 9.5) << lat_deg;
    // Negative control: a 15 deg mask hides satellites.
    const VisibilityStatistics high = visibility_over_a_day(lat_deg, 15.0);
    EXPECT_LT(high.mean, s.mean - 1.0) << lat_deg;
    EXPECT_LT(high.min, s.min) << lat_deg;
  }
}

TEST(GpsConstellation, BadInputsAreRejected) {
  const GpsConstellation c = GpsConstellation::baseline_24();
  EXPECT_THROW(c.position_ecef_m(0, std::numeric_limits<double>::quiet_NaN()), std::invalid_argument);
  EXPECT_THROW(c.position_ecef_m(0, 1e12), std::invalid_argument);
  EXPECT_THROW(c.position_ecef_m(24, 0.0), std::out_of_range);
  EXPECT_THROW(GpsConstellation({GpsOrbit{"X", 0.0, 0.0, 0.0, 1000.0}}), std::invalid_argument);
  PseudorangeConfig bad;
  bad.mask_angle_rad = 95.0 * kDeg;
  EXPECT_THROW(PseudorangeModel{bad}, std::invalid_argument);
  bad = PseudorangeConfig{};
  bad.noise_sigma_m = -1.0;
  EXPECT_THROW(PseudorangeModel{bad}, std::invalid_argument);
}

}  // namespace
}  // namespace fedsim::nav
