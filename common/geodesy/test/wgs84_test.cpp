// Tests of WGS-84 geodesy and J2 gravity.
#include "common/geodesy/wgs84.hpp"
#include "common/units/units.hpp"

#include <GeographicLib/NormalGravity.hpp>
#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <cmath>

namespace fedsim {
namespace {

constexpr double kPi = units::kPi;
constexpr double kDeg = kPi / 180.0;

TEST(Wgs84, KnownEcefPoints) {
  const Eigen::Vector3d origin = Wgs84::ecef_from_geodetic({0.0, 0.0, 0.0});
  EXPECT_NEAR((origin - Eigen::Vector3d(6378137.0, 0.0, 0.0)).norm(), 0.0, 1e-9);
  const Eigen::Vector3d pole = Wgs84::ecef_from_geodetic({90.0 * kDeg, 0.0, 100.0});
  EXPECT_NEAR(pole.z(), 6356752.314245 + 100.0, 1e-6);  // b = 6,356,752.3142 m
  EXPECT_NEAR(std::hypot(pole.x(), pole.y()), 0.0, 1e-6);
  const Eigen::Vector3d east = Wgs84::ecef_from_geodetic({0.0, 90.0 * kDeg, 0.0});
  EXPECT_NEAR(east.y(), 6378137.0, 1e-6);
}

TEST(Wgs84, GeodeticRoundTrip) {
  for (double lat : {-89.999, -45.0, 0.0, 12.3, 51.5, 89.999}) {
    for (double lon : {-179.9, -3.0, 0.0, 100.0}) {
      for (double alt : {-400.0, 0.0, 9144.0, 400000.0}) {
        const GeodeticPosition in{lat * kDeg, lon * kDeg, alt};
        const GeodeticPosition out = Wgs84::geodetic_from_ecef(Wgs84::ecef_from_geodetic(in));
        EXPECT_NEAR(out.lat_rad, in.lat_rad, 1e-12);
        EXPECT_NEAR(out.lon_rad, in.lon_rad, 1e-12);
        EXPECT_NEAR(out.alt_m, in.alt_m, 1e-6);
      }
    }
  }
}

TEST(Wgs84, NedAxesAreOrthonormalAndPointTheRightWay) {
  const Eigen::Matrix3d c00 = Wgs84::ned_from_ecef(0.0, 0.0);
  EXPECT_TRUE((c00 * Eigen::Vector3d::UnitZ()).isApprox(Eigen::Vector3d::UnitX()));  // north
  EXPECT_TRUE((c00 * Eigen::Vector3d::UnitY()).isApprox(Eigen::Vector3d::UnitY()));  // east
  EXPECT_TRUE((c00 * Eigen::Vector3d::UnitX()).isApprox(-Eigen::Vector3d::UnitZ()));  // up
  const double lat = 37.0 * kDeg;
  const double lon = -122.0 * kDeg;
  const Eigen::Matrix3d c = Wgs84::ned_from_ecef(lat, lon);
  EXPECT_TRUE((c * c.transpose()).isApprox(Eigen::Matrix3d::Identity(), 1e-14));
  EXPECT_NEAR(c.determinant(), 1.0, 1e-14);
  // "Down" is the ellipsoid normal: moving down 1 m changes only the height.
  const GeodeticPosition p{lat, lon, 500.0};
  const Eigen::Vector3d down_ecef = c.transpose() * Eigen::Vector3d::UnitZ();
  const GeodeticPosition q = Wgs84::geodetic_from_ecef(Wgs84::ecef_from_geodetic(p) + down_ecef);
  EXPECT_NEAR(q.alt_m, 499.0, 1e-9);
  EXPECT_NEAR(q.lat_rad, lat, 1e-14);
}

TEST(Wgs84, SurfaceGravityAtEquatorAndPole) {
  // WGS-84 normal gravity (TR8350.2 eq. 4-1): 9.7803253359 m/s² at the equator,
  // 9.8321849378 m/s² at the poles. The J2 field leaves out J4 and higher zonal terms, worth
  // about 4e-5 m/s² at the equator and 1.2e-4 m/s² at the poles.
  const Eigen::Vector3d equator = Wgs84::ecef_from_geodetic({0.0, 0.0, 0.0});
  const Eigen::Vector3d pole = Wgs84::ecef_from_geodetic({90.0 * kDeg, 0.0, 0.0});
  EXPECT_NEAR(Wgs84::gravity_ecef(equator).norm(), 9.7803253359, 6e-5);
  EXPECT_NEAR(Wgs84::gravity_ecef(pole).norm(), 9.8321849378, 1.5e-4);
}

TEST(Wgs84, GravityFollowsNormalGravityAtAllLatitudes) {
  const GeographicLib::NormalGravity& normal = GeographicLib::NormalGravity::WGS84();
  for (double lat_deg = -90.0; lat_deg <= 90.0; lat_deg += 7.5) {
    const double lat = lat_deg * kDeg;
    const Eigen::Vector3d r = Wgs84::ecef_from_geodetic({lat, 0.3, 1000.0});
    const Eigen::Vector3d g_ned = Wgs84::ned_from_ecef(lat, 0.3) * Wgs84::gravity_ecef(r);
    double gy = 0.0;
    double gz = 0.0;
    normal.Gravity(lat_deg, 1000.0, gy, gz);  // gz is up, negative
    // Same J4 truncation as above: within 1.5e-4 m/s² down, 1e-4 m/s² north (1e-5 rad).
    EXPECT_NEAR(g_ned.z(), -gz, 1.5e-4) << lat_deg;
    EXPECT_NEAR(g_ned.x(), gy, 1e-4) << lat_deg;
    EXPECT_NEAR(g_ned.y(), 0.0, 1e-12) << lat_deg;
  }
}

TEST(Wgs84, GravitationAtNasaCheckCaseStart) {
  // NASA TM-2015-218675 check cases: "localGravity" at 30,000 ft over 0N 0E is
  // 32.1065359519 ft/s² (the J2 gravitation magnitude, without the centripetal term).
  const Eigen::Vector3d r = Wgs84::ecef_from_geodetic({0.0, 0.0, 9144.0});
  EXPECT_NEAR(Wgs84::gravitation_ecef(r).norm() / units::kFtToM, 32.1065359519, 1e-9);
}

TEST(Wgs84, RadiiOfCurvature) {
  EXPECT_NEAR(Wgs84::meridian_radius_m(0.0), 6335439.327, 1e-3);
  EXPECT_NEAR(Wgs84::prime_vertical_radius_m(0.0), 6378137.0, 1e-9);
  EXPECT_NEAR(Wgs84::meridian_radius_m(kPi / 2), Wgs84::prime_vertical_radius_m(kPi / 2), 1e-6);
}

}  // namespace
}  // namespace fedsim
