// GDOP, PDOP, HDOP, VDOP, TDOP from (H^T H)^-1 in the local ENU frame.
#include "federates/nav/model/gps/dilution_of_precision.hpp"

#include "federates/nav/model/gps/satellite_geometry.hpp"

#include <Eigen/Dense>

#include <cmath>

namespace fedsim::nav {

namespace {
constexpr double kMinEigenvalueRatio = 1e-12;
}  // namespace

std::optional<Eigen::Matrix4d> inverse_of_normal_matrix(const Eigen::Matrix4d& normal) {
  if (!normal.allFinite()) return std::nullopt;
  const Eigen::SelfAdjointEigenSolver<Eigen::Matrix4d> eigen(normal);
  if (eigen.info() != Eigen::Success) return std::nullopt;
  const Eigen::Vector4d& lambda = eigen.eigenvalues();  // ascending
  if (!(lambda[3] > 0.0) || lambda[0] <= kMinEigenvalueRatio * lambda[3]) return std::nullopt;
  return eigen.eigenvectors() * lambda.cwiseInverse().asDiagonal() *
         eigen.eigenvectors().transpose();
}

std::optional<DilutionOfPrecision> dilution_of_precision_from_geometry(
    const Eigen::Vector3d& receiver_ecef_m, const Eigen::MatrixX4d& geometry) {
  if (geometry.rows() < 4 || !geometry.allFinite() || !receiver_ecef_m.allFinite()) {
    return std::nullopt;
  }
  const std::optional<Eigen::Matrix4d> inverse =
      inverse_of_normal_matrix(geometry.transpose() * geometry);
  if (!inverse) return std::nullopt;
  const Eigen::Matrix4d& q_ecef = *inverse;
  Eigen::Matrix4d rotation = Eigen::Matrix4d::Identity();
  rotation.topLeftCorner<3, 3>() = enu_from_ecef(receiver_ecef_m);
  DilutionOfPrecision dop;
  dop.covariance_enu_clock = rotation * q_ecef * rotation.transpose();
  const Eigen::Matrix4d& q = dop.covariance_enu_clock;
  dop.hdop = std::sqrt(q(0, 0) + q(1, 1));
  dop.vdop = std::sqrt(q(2, 2));
  dop.pdop = std::sqrt(q(0, 0) + q(1, 1) + q(2, 2));
  dop.tdop = std::sqrt(q(3, 3));
  dop.gdop = std::sqrt(q.trace());
  return dop;
}

std::optional<DilutionOfPrecision> dilution_of_precision(
    const Eigen::Vector3d& receiver_ecef_m, const std::vector<Eigen::Vector3d>& satellites_ecef_m) {
  Eigen::MatrixX4d h(static_cast<Eigen::Index>(satellites_ecef_m.size()), 4);
  for (std::size_t i = 0; i < satellites_ecef_m.size(); ++i) {
    const LookAngles look = look_angles(receiver_ecef_m, satellites_ecef_m[i]);
    h.row(static_cast<Eigen::Index>(i)) << -look.line_of_sight_ecef.transpose(), 1.0;
  }
  return dilution_of_precision_from_geometry(receiver_ecef_m, h);
}

}  // namespace fedsim::nav
