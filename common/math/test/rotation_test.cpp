// Tests of the Euler/quaternion/DCM helpers, including the +-90 deg pitch cases.
#include "common/math/rotation.hpp"
#include "common/units/units.hpp"

#include <gtest/gtest.h>

#include <cmath>

#include "common/math/integrator.hpp"

namespace fedsim {
namespace {

constexpr double kPi = units::kPi;
constexpr double kDeg = kPi / 180.0;

// Independent construction: parent_from_body = Rz(psi) Ry(theta) Rx(phi).
Eigen::Matrix3d elementary_dcm(const EulerAngles& e) {
  return (Eigen::AngleAxisd(e.psi_rad, Eigen::Vector3d::UnitZ()) *
          Eigen::AngleAxisd(e.theta_rad, Eigen::Vector3d::UnitY()) *
          Eigen::AngleAxisd(e.phi_rad, Eigen::Vector3d::UnitX()))
      .toRotationMatrix();
}

TEST(Rotation, QuaternionFromEulerMatchesElementaryRotations) {
  for (double phi : {-170.0, -30.0, 0.0, 45.0, 179.0}) {
    for (double theta : {-89.9, -45.0, 0.0, 10.0, 89.9}) {
      for (double psi : {-135.0, 0.0, 90.0, 180.0}) {
        const EulerAngles e{phi * kDeg, theta * kDeg, psi * kDeg};
        const Eigen::Quaterniond q = quaternion_from_euler(e);
        EXPECT_NEAR(q.norm(), 1.0, 1e-15);
        EXPECT_TRUE(dcm_from_quaternion(q).isApprox(elementary_dcm(e), 1e-14));
        // Same convention as Eigen: v_parent = q * v_body.
        EXPECT_TRUE(q.toRotationMatrix().isApprox(dcm_from_quaternion(q), 1e-14));
      }
    }
  }
}

TEST(Rotation, EulerRoundTripIncludingNearVertical) {
  for (double phi : {-179.0, -60.0, 0.0, 33.0, 150.0}) {
    for (double theta : {-89.9, -60.0, 0.0, 45.0, 89.9}) {
      for (double psi : {-170.0, -10.0, 0.0, 75.0, 179.5}) {
        const EulerAngles in{phi * kDeg, theta * kDeg, psi * kDeg};
        const EulerAngles out = euler_from_quaternion(quaternion_from_euler(in));
        EXPECT_NEAR(out.phi_rad, in.phi_rad, 1e-10) << phi << " " << theta << " " << psi;
        EXPECT_NEAR(out.theta_rad, in.theta_rad, 1e-12) << phi << " " << theta << " " << psi;
        EXPECT_NEAR(out.psi_rad, in.psi_rad, 1e-10) << phi << " " << theta << " " << psi;
      }
    }
  }
}

TEST(Rotation, ExactlyVerticalPitchKeepsTheRotation) {
  for (double theta : {90.0, -90.0}) {
    const EulerAngles in{25.0 * kDeg, theta * kDeg, 70.0 * kDeg};
    const Eigen::Quaterniond q = quaternion_from_euler(in);
    const EulerAngles out = euler_from_quaternion(q);
    EXPECT_NEAR(out.theta_rad, in.theta_rad, 1e-7);
    EXPECT_NEAR(out.phi_rad, 0.0, 1e-7);
    // Only psi - phi (nose up) or psi + phi (nose down) is defined at the singularity.
    const double expected_psi = theta > 0 ? 45.0 * kDeg : 95.0 * kDeg;
    EXPECT_NEAR(out.psi_rad, expected_psi, 1e-7);
    EXPECT_TRUE(dcm_from_euler(out).isApprox(dcm_from_quaternion(q), 1e-7));
    EXPECT_TRUE(std::isfinite(out.phi_rad) && std::isfinite(out.psi_rad));
  }
}

TEST(Rotation, QuaternionRateIsHalfQTimesOmega) {
  const Eigen::Quaterniond q = quaternion_from_euler({0.3, -0.7, 2.0});
  const Eigen::Vector3d w(0.4, -1.1, 0.25);
  const Eigen::Quaterniond expected = q * Eigen::Quaterniond(0.0, w.x(), w.y(), w.z());
  const Eigen::Vector4d rate = quaternion_rate(to_e0123(q), w, 10.0);
  EXPECT_TRUE(rate.isApprox(0.5 * to_e0123(expected), 1e-14));
}

TEST(Rotation, AlgebraicConstraintPullsTheNormBackToOne) {
  // With omega = 0 only the constraint term acts: d|q|^2/dt = 2 k (1 - |q|^2) |q|^2.
  using Q = Integrator<4>::Vector;
  Integrator<4> integrator(IntegrationMethod::kRk4);
  Q q = 1.05 * to_e0123(quaternion_from_euler({0.1, 0.2, 0.3}));
  const double h = 0.01;
  const double k = 0.5 / h;  // k h = 0.5 <= 1
  const auto f = [&](double, const Q& e) { return Q(quaternion_rate(e, Eigen::Vector3d::Zero(), k)); };
  for (int i = 0; i < 100; ++i) integrator.step(i * h, h, q, f);
  EXPECT_NEAR(q.norm(), 1.0, 1e-12);
}

TEST(Rotation, IntegratedRateMatchesClosedFormRotation) {
  using Q = Integrator<4>::Vector;
  const Eigen::Vector3d w(0.3, -0.8, 1.5);
  const Eigen::Quaterniond q0 = quaternion_from_euler({0.5, 0.2, -1.0});
  Integrator<4> integrator(IntegrationMethod::kRk4);
  Q q = to_e0123(q0);
  const auto f = [&](double, const Q& e) { return Q(quaternion_rate(e, w, 0.0)); };
  const double h = 0.001;
  for (int i = 0; i < 2000; ++i) integrator.step(i * h, h, q, f);
  const Eigen::Quaterniond exact = q0 * Eigen::Quaterniond(Eigen::AngleAxisd(w.norm() * 2.0, w.normalized()));
  EXPECT_LT((from_e0123(q).toRotationMatrix() - exact.toRotationMatrix()).norm(), 1e-12);
}

TEST(Rotation, SkewAndWrap) {
  const Eigen::Vector3d a(1.0, -2.0, 3.0);
  const Eigen::Vector3d b(0.5, 4.0, -1.0);
  EXPECT_TRUE((skew(a) * b).isApprox(a.cross(b)));
  EXPECT_NEAR(wrap_pi(3.0 * kPi), kPi, 1e-12);
  EXPECT_NEAR(wrap_pi(-kPi), kPi, 1e-12);
  EXPECT_NEAR(wrap_pi(-0.5), -0.5, 1e-15);
}

}  // namespace
}  // namespace fedsim
