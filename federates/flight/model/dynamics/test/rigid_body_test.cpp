// Tests of the rigid-body equations of motion: invariants, analytic solutions, round trips.
#include "flight/model/dynamics/rigid_body.hpp"
#include "common/units/units.hpp"

#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <cmath>
#include <iostream>

#include "common/util/allocation_counter.hpp"

namespace fedsim::flight {
namespace {

constexpr double kPi = units::kPi;
constexpr double kDeg = kPi / 180.0;

class NoForces : public ForceSource {
 public:
  Wrench forces(const RigidBodyState&, double) override { return {}; }
};

RigidBodyConfig flat_config(IntegrationMethod method = IntegrationMethod::kRk4) {
  RigidBodyConfig config;
  config.earth.kind = EarthModelKind::kFlat;
  config.method = method;
  return config;
}

// Asymmetric body with a product of inertia (the brick of NASA case 2 plus an Ixz).
MassProperties tumbler() { return MassProperties::from_moments(2.0, 0.0026, 0.0084, 0.0098, 0.0007); }

Eigen::Vector3d inertial_momentum(const RigidBody& body) {
  const RigidBodyState s = body.state();
  return s.attitude.toRotationMatrix() * (body.dynamics().mass_properties().inertia_kgm2 * s.omega_body_radps);
}

double rotational_energy(const RigidBody& body) {
  const Eigen::Vector3d w = body.state().omega_body_radps;
  return 0.5 * w.dot(body.dynamics().mass_properties().inertia_kgm2 * w);
}

InitialConditions tumbling_start() {
  InitialConditions ic;
  ic.position.alt_m = 1000.0;
  ic.attitude = {0.2, -0.4, 1.0};
  ic.omega_body_radps = {10.0 * kDeg, 20.0 * kDeg, 30.0 * kDeg};
  return ic;
}

// Largest |1 - |q|| over 1e5 steps (1000 s) of a fast tumble (~1 rev/s) at h = 0.01 s.
double worst_norm_error(double constraint_kh) {
  RigidBodyConfig config = flat_config();
  config.quaternion_constraint_kh = constraint_kh;
  RigidBody body(config, tumbler());
  InitialConditions ic = tumbling_start();
  ic.omega_body_radps = {3.0, -5.0, 4.0};
  body.reset(ic);
  NoForces none;
  double worst = 0.0;
  for (int i = 0; i < 100000; ++i) {
    body.step(0.01, 1, none);
    worst = std::max(worst, std::abs(body.state().attitude.norm() - 1.0));
  }
  return worst;
}

TEST(RigidBody, QuaternionNormHeldOverLongTumble) {
  const double with_constraint = worst_norm_error(0.5);
  const double without_constraint = worst_norm_error(0.0);
  EXPECT_LT(with_constraint, 1e-9);
  // RK4 alone shrinks |q| steadily (|R(i theta)| < 1); the constraint (eqs 3.67-3.70) is
  // what holds it.
  EXPECT_GT(without_constraint, 50.0 * with_constraint);
  std::cout << "quaternion norm error over 1e5 steps: with constraint " << with_constraint
            << ", without " << without_constraint << "\n";
}

// With the default (per-method) constraint gain every integrator keeps |q| = 1: a gain of 0.5
// is outside the real stability interval of AB3 and AB4 and made them diverge.
TEST(RigidBody, QuaternionNormHeldByEveryIntegratorWithItsDefaultGain) {
  for (const auto method : {IntegrationMethod::kEuler, IntegrationMethod::kRk4,
                            IntegrationMethod::kAb2, IntegrationMethod::kAb3,
                            IntegrationMethod::kAb4}) {
    RigidBody body(flat_config(method), tumbler());
    InitialConditions ic = tumbling_start();
    ic.omega_body_radps = {3.0, -5.0, 4.0};
    body.reset(ic);
    NoForces none;
    double worst = 0.0;
    for (int i = 0; i < 2000; ++i) {  // 20 s
      body.step(0.01, 1, none);
      worst = std::max(worst, std::abs(body.state().attitude.norm() - 1.0));
    }
    // Bounded, not diverging (before the fix: |q| 1.149 with AB3, NaN with AB4). Euler's own
    // growth of |q| per step, (omega h / 2)^2 / 2, is what leaves it at a few 1e-3 here.
    EXPECT_LT(worst, method == IntegrationMethod::kEuler ? 1e-2 : 1e-4)
        << "method " << static_cast<int>(method);
  }
}

TEST(RigidBody, TorqueFreeBodyConservesMomentumAndEnergy) {
  RigidBody body(flat_config(), tumbler());
  body.reset(tumbling_start());
  NoForces none;
  const Eigen::Vector3d h0 = inertial_momentum(body);
  const double e0 = rotational_energy(body);
  double worst_h = 0.0;
  double worst_e = 0.0;
  for (int i = 0; i < 6000; ++i) {  // 60 s
    body.step(0.01, 1, none);
    worst_h = std::max(worst_h, (inertial_momentum(body) - h0).norm() / h0.norm());
    worst_e = std::max(worst_e, std::abs(rotational_energy(body) - e0) / e0);
  }
  EXPECT_LT(worst_h, 1e-10);
  EXPECT_LT(worst_e, 1e-10);
  std::cout << "torque-free 60 s, RK4 h = 0.01 s: |dH|/|H| " << worst_h << ", dE/E " << worst_e
            << "\n";
  // The body really does tumble (intermediate-axis motion changes the body rates a lot).
  EXPECT_GT((body.state().omega_body_radps - tumbling_start().omega_body_radps).norm(), 0.1);
}

TEST(RigidBody, MomentEquationsMatchTheBooksScalarForm) {
  // Seed eqs 3.104-3.106 with all products of inertia, checked against omega' from the model.
  const double ix = 3.0, iy = 5.0, iz = 7.0, ixz = 0.6, ixy = -0.2, iyz = 0.3;
  const MassProperties mass = MassProperties::from_moments(10.0, ix, iy, iz, ixz, ixy, iyz);
  const RigidBodyDynamics dynamics(EarthModel({EarthModelKind::kFlat}), mass);
  RigidBodyState state;
  state.omega_body_radps = {0.7, -1.2, 0.4};
  Wrench wrench;
  wrench.moment_body_nm = {1.5, -0.5, 2.5};
  const Eigen::Vector3d wd = dynamics.accelerations(state, wrench).omega_dot_body_radps2;
  const double p = 0.7, q = -1.2, r = 0.4;
  const double pd = wd.x(), qd = wd.y(), rd = wd.z();
  EXPECT_NEAR(ix * pd + q * r * (iz - iy) - iyz * (q * q - r * r) - ixz * (rd + p * q) -
                  ixy * (qd - p * r), 1.5, 1e-12);
  EXPECT_NEAR(iy * qd + p * r * (ix - iz) + ixz * (p * p - r * r) - iyz * (rd - p * q) -
                  ixy * (pd + q * r), -0.5, 1e-12);
  EXPECT_NEAR(iz * rd + p * q * (iy - ix) - ixy * (p * p - q * q) - ixz * (pd - q * r) -
                  iyz * (qd + p * r), 2.5, 1e-12);
}

TEST(RigidBody, RotorMomentumGivesGyroscopicYawInPitch) {
  // A rotor spinning about +x (clockwise seen from behind) pitched nose-up yaws the nose right.
  const RigidBodyDynamics dynamics(EarthModel({EarthModelKind::kFlat}),
                                   MassProperties::from_moments(1000.0, 1000.0, 2000.0, 2500.0));
  RigidBodyState state;
  state.omega_body_radps = {0.0, 0.2, 0.0};
  Wrench wrench;
  wrench.rotor_momentum_body_kgm2ps = {500.0, 0.0, 0.0};
  const Eigen::Vector3d wd = dynamics.accelerations(state, wrench).omega_dot_body_radps2;
  EXPECT_NEAR(wd.z(), 0.2 * 500.0 / 2500.0, 1e-15);  // r' = q hx / Iz (eq. 3.112)
  EXPECT_NEAR(wd.x(), 0.0, 1e-15);
  EXPECT_NEAR(wd.y(), 0.0, 1e-15);
}

TEST(RigidBody, DraglessSphereFallsAsTheAnalyticSolution) {
  RigidBodyConfig config = flat_config();
  config.earth.flat_gravity_mps2 = 9.81;
  RigidBody body(config, MassProperties::from_moments(5.0, 0.1, 0.1, 0.1));
  InitialConditions ic;
  ic.position.alt_m = 3000.0;
  ic.velocity_ned_mps = {40.0, -10.0, -25.0};
  body.reset(ic);
  NoForces none;
  for (int i = 0; i < 2000; ++i) body.step(0.01, 1, none);  // 20 s
  const double t = body.time_s();
  const RigidBodyOutputs out = body.outputs();
  const Eigen::Vector3d p = body.state().position_m;
  EXPECT_NEAR(t, 20.0, 1e-9);
  EXPECT_NEAR(p.x(), 40.0 * t, 1e-8);
  EXPECT_NEAR(p.y(), -10.0 * t, 1e-8);
  EXPECT_NEAR(out.geodetic.alt_m, 3000.0 + 25.0 * t - 0.5 * 9.81 * t * t, 1e-8);
  EXPECT_NEAR(out.velocity_ned_mps.z(), -25.0 + 9.81 * t, 1e-9);
}

TEST(RigidBody, EulerRoundTripThroughTheStateIncludingVertical) {
  for (EarthModelKind kind : {EarthModelKind::kFlat, EarthModelKind::kWgs84}) {
    RigidBodyConfig config;
    config.earth.kind = kind;
    config.earth.origin_lat_rad = 0.9;
    RigidBody body(config, tumbler());
    for (double theta : {-90.0, -89.9, 0.0, 45.0, 89.9, 90.0}) {
      InitialConditions ic;
      ic.position = {0.9, -0.2, 500.0};
      ic.attitude = {30.0 * kDeg, theta * kDeg, -120.0 * kDeg};
      body.reset(ic);
      const RigidBodyOutputs out = body.outputs();
      EXPECT_NEAR(out.euler.theta_rad, theta * kDeg, 1e-7) << theta;
      EXPECT_TRUE(out.ned_from_body.isApprox(dcm_from_euler(ic.attitude), 1e-9)) << theta;
      if (std::abs(theta) < 90.0) {
        EXPECT_NEAR(out.euler.phi_rad, 30.0 * kDeg, 1e-9) << theta;
        EXPECT_NEAR(out.euler.psi_rad, -120.0 * kDeg, 1e-9) << theta;
      }
    }
  }
}

TEST(RigidBody, FlatEarthGeodeticMapping) {
  RigidBodyConfig config = flat_config();
  config.earth.origin_lat_rad = 52.0 * kDeg;
  config.earth.origin_lon_rad = -1.0 * kDeg;
  RigidBody body(config, tumbler());
  InitialConditions ic;
  ic.position = {52.01 * kDeg, -0.98 * kDeg, 120.0};
  body.reset(ic);
  const RigidBodyOutputs out = body.outputs();
  EXPECT_NEAR(out.geodetic.lat_rad, ic.position.lat_rad, 1e-15);
  EXPECT_NEAR(out.geodetic.lon_rad, ic.position.lon_rad, 1e-15);
  EXPECT_NEAR(body.state().position_m.z(), -120.0, 1e-12);
  // 0.01 deg of latitude is ~1113 m at 52 deg N.
  EXPECT_NEAR(body.state().position_m.x(), 1113.0, 1.0);
}

TEST(RigidBody, SpecificForceAtAnOffsetPoint) {
  RigidBodyAccelerations acc;
  acc.specific_force_body_mps2 = {0.0, 0.0, -9.81};
  acc.omega_dot_body_radps2 = {0.0, 0.5, 0.0};
  const Eigen::Vector3d omega(0.0, 0.0, 2.0);
  const Eigen::Vector3d eye(3.0, 0.0, -1.0);
  const Eigen::Vector3d f = RigidBodyDynamics::specific_force_at_body(acc, omega, eye);
  // Centripetal -r^2 x = -12 along x; pitch acceleration q' x r adds (0.5 x -1 ...) terms.
  EXPECT_NEAR(f.x(), -12.0 + 0.5 * -1.0, 1e-12);
  EXPECT_NEAR(f.y(), 0.0, 1e-12);
  EXPECT_NEAR(f.z(), -9.81 - 0.5 * 3.0, 1e-12);
}

TEST(RigidBody, AllMethodsAgreeOnATumbleAndRestartOnReposition) {
  RigidBody reference(flat_config(), tumbler());
  reference.reset(tumbling_start());
  NoForces none;
  for (int i = 0; i < 200; ++i) reference.step(0.01, 4, none);
  for (IntegrationMethod method : {IntegrationMethod::kAb2, IntegrationMethod::kAb3,
                                   IntegrationMethod::kAb4, IntegrationMethod::kEuler}) {
    RigidBody body(flat_config(method), tumbler());
    body.reset(tumbling_start());
    for (int i = 0; i < 200; ++i) body.step(0.01, 4, none);
    const double tolerance = method == IntegrationMethod::kEuler ? 1e-2 : 1e-5;
    EXPECT_LT((body.state().omega_body_radps - reference.state().omega_body_radps).norm(), tolerance)
        << to_string(method);
  }
}

TEST(RigidBody, StepDoesNotAllocate) {
  for (EarthModelKind kind : {EarthModelKind::kFlat, EarthModelKind::kWgs84}) {
    RigidBodyConfig config;
    config.earth.kind = kind;
    config.method = IntegrationMethod::kAb3;
    RigidBody body(config, tumbler());
    body.reset(tumbling_start());
    NoForces none;
    const util::AllocationScope scope;
    for (int i = 0; i < 100; ++i) {
      body.step(0.02, 2, none);
      const RigidBodyOutputs out = body.outputs();
      EXPECT_TRUE(std::isfinite(out.geodetic.alt_m));
    }
    EXPECT_EQ(scope.allocations(), 0u);
  }
}

TEST(MassProperties, RejectsUnphysicalInertia) {
  EXPECT_NO_THROW(tumbler().validate());
  EXPECT_THROW(MassProperties::from_moments(0.0, 1, 1, 1).validate(), std::invalid_argument);
  EXPECT_THROW(MassProperties::from_moments(1.0, 1, 1, 3).validate(), std::invalid_argument);
  EXPECT_THROW(MassProperties::from_moments(1.0, 1, 1, 1, 2.0).validate(), std::invalid_argument);
}

}  // namespace
}  // namespace fedsim::flight
