// Tests of the rigid body on the rotating WGS-84 earth against an independent inertial solution.
#include <gtest/gtest.h>
#include "common/units/units.hpp"

#include <Eigen/Geometry>
#include <cmath>

#include "flight/model/dynamics/rigid_body.hpp"

namespace fedsim::flight {
namespace {

constexpr double kPi = units::kPi;
constexpr double kDeg = kPi / 180.0;

class NoForces : public ForceSource {
 public:
  Wrench forces(const RigidBodyState&, double) override { return {}; }
};

// Holds the body up with exactly the force that cancels gravity and the centripetal term.
class Table : public ForceSource {
 public:
  explicit Table(double mass_kg) : mass_kg_(mass_kg) {}
  Wrench forces(const RigidBodyState& s, double) override {
    Wrench w;
    const Eigen::Vector3d g = Wgs84::gravity_ecef(s.position_m);
    w.force_body_n = s.attitude.conjugate() * (-mass_kg_ * g);
    return w;
  }

 private:
  double mass_kg_;
};

RigidBodyConfig round_config() {
  RigidBodyConfig config;
  config.earth.kind = EarthModelKind::kWgs84;
  return config;
}

const MassProperties kSphere = MassProperties::from_moments(14.59, 4.88, 4.88, 4.88);

TEST(RotatingEarth, SupportedBodyStaysPutRelativeToTheEarth) {
  RigidBody body(round_config(), kSphere);
  InitialConditions ic;
  ic.position = {45.0 * kDeg, 7.0 * kDeg, 300.0};
  ic.attitude = {0.1, 0.05, 2.0};
  ic.omega_relative_to_earth = true;  // turning with the earth
  body.reset(ic);
  Table table(kSphere.mass_kg);
  for (int i = 0; i < 6000; ++i) body.step(0.01, 1, table);  // 60 s
  const RigidBodyOutputs out = body.outputs();
  EXPECT_NEAR(out.geodetic.alt_m, 300.0, 1e-6);
  EXPECT_NEAR(out.geodetic.lat_rad, ic.position.lat_rad, 1e-12);
  EXPECT_NEAR(out.geodetic.lon_rad, ic.position.lon_rad, 1e-12);
  EXPECT_LT(out.velocity_ned_mps.norm(), 1e-8);
  EXPECT_NEAR(out.euler.psi_rad, 2.0, 1e-9);
  EXPECT_LT(out.omega_body_wrt_earth_radps.norm(), 1e-15);
}

TEST(RotatingEarth, FreeFallMatchesAnInertialFrameSolution) {
  // The same throw integrated in ECI (no Coriolis or centripetal terms; J2 gravitation is
  // axisymmetric, so the ECEF expression holds in ECI), then rotated into ECEF.
  RigidBody body(round_config(), kSphere);
  InitialConditions ic;
  ic.position = {30.0 * kDeg, -60.0 * kDeg, 1000.0};
  ic.velocity_ned_mps = {150.0, -80.0, -200.0};
  body.reset(ic);
  const RigidBodyState start = body.state();
  const Eigen::Vector3d w = Wgs84::earth_rate_ecef();
  Eigen::Matrix<double, 6, 1> y;
  y << start.position_m, start.velocity_mps + w.cross(start.position_m);
  const auto f = [](double, const Eigen::Matrix<double, 6, 1>& s) {
    Eigen::Matrix<double, 6, 1> d;
    d << s.tail<3>(), Wgs84::gravitation_ecef(s.head<3>());
    return d;
  };
  Integrator<6> inertial(IntegrationMethod::kRk4);
  NoForces none;
  const double h = 0.005;
  for (int i = 0; i < 6000; ++i) {  // 30 s
    inertial.step(i * h, h, y, f);
    body.step(h, 1, none);
  }
  const double t = body.time_s();
  const Eigen::Matrix3d ecef_from_eci =
      Eigen::AngleAxisd(-wgs84::kEarthRateRadps * t, Eigen::Vector3d::UnitZ()).toRotationMatrix();
  const Eigen::Vector3d r_expected = ecef_from_eci * y.head<3>();
  const Eigen::Vector3d v_expected = ecef_from_eci * (y.tail<3>() - w.cross(y.head<3>()));
  EXPECT_LT((body.state().position_m - r_expected).norm(), 1e-6);
  EXPECT_LT((body.state().velocity_mps - v_expected).norm(), 1e-8);
  // Coriolis matters at this size: the eastward drift over 30 s is metres.
  const Eigen::Vector3d r_no_rotation = y.head<3>();
  EXPECT_GT((r_expected - r_no_rotation).norm(), 10.0);
}

TEST(RotatingEarth, InertiallyFixedBodyRollsAgainstTheEarthAtTheEquator) {
  // Body level and heading north at 0N 0E with zero inertial rate: the local NED frame turns
  // under it about north at the earth rate, so roll decreases as -W t (NASA check case 1 data:
  // -0.1254 deg after 30 s).
  RigidBody body(round_config(), kSphere);
  InitialConditions ic;
  ic.position = {0.0, 0.0, 9144.0};
  body.reset(ic);
  NoForces none;
  for (int i = 0; i < 3000; ++i) body.step(0.01, 1, none);
  EXPECT_NEAR(body.outputs().euler.phi_rad / kDeg, -0.12540, 5e-5);
  EXPECT_LT(body.outputs().omega_body_radps.norm(), 1e-18);
}

TEST(RotatingEarth, EarthRelativeRatesAddTheEarthRate) {
  RigidBody body(round_config(), kSphere);
  InitialConditions ic;
  ic.attitude = {0.0, 0.0, 90.0 * kDeg};  // heading east at the equator: body y points south
  ic.omega_relative_to_earth = true;
  body.reset(ic);
  const Eigen::Vector3d omega = body.outputs().omega_body_radps;
  EXPECT_NEAR(omega.x(), 0.0, 1e-15);
  EXPECT_NEAR(omega.y(), -wgs84::kEarthRateRadps, 1e-15);
  EXPECT_NEAR(omega.z(), 0.0, 1e-15);
}

}  // namespace
}  // namespace fedsim::flight
