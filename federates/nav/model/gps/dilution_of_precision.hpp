// Dilution of precision (seed 6.11; Misra & Enge, Global Positioning System: Signals,
// Measurements, and Performance, 2nd ed. 2006, ch. 6 on position estimation and DOP).
// With H the n x 4 geometry matrix of the linearised pseudorange equations (rows
// [-los_ecef^T, 1], clock in metres) and Q = (H^T H)^-1 with the position block rotated into
// the local ENU frame (Q_enu = R Q_pos R^T, R = enu_from_ecef):
//   GDOP = sqrt(trace Q), PDOP = sqrt(Q_EE + Q_NN + Q_UU), HDOP = sqrt(Q_EE + Q_NN),
//   VDOP = sqrt(Q_UU), TDOP = sqrt(Q_tt).
// A position error's RMS is DOP x the (equal, independent) pseudorange error sigma.
#pragma once

#include <Eigen/Core>

#include <optional>
#include <vector>

namespace fedsim::nav {

struct DilutionOfPrecision {
  double gdop = 0.0;
  double pdop = 0.0;
  double hdop = 0.0;
  double vdop = 0.0;
  double tdop = 0.0;
  Eigen::Matrix4d covariance_enu_clock = Eigen::Matrix4d::Zero();  // Q: E, N, U, clock [-]
};

/// (H^T H)^-1 from its eigen-decomposition, or nullopt if H^T H is singular: its smallest
/// eigenvalue is below 1e-12 times the largest (e.g. all satellites on one cone about the
/// receiver, the classic degenerate geometry, or fewer than 4 distinct directions).
std::optional<Eigen::Matrix4d> inverse_of_normal_matrix(const Eigen::Matrix4d& normal);

/// The DOPs of the geometry, or nullopt with fewer than 4 satellites or a singular geometry.
/// Positions ECEF [m].
std::optional<DilutionOfPrecision> dilution_of_precision(
    const Eigen::Vector3d& receiver_ecef_m, const std::vector<Eigen::Vector3d>& satellites_ecef_m);

/// The same from the n x 4 geometry matrix H (ECEF line of sight and clock columns).
std::optional<DilutionOfPrecision> dilution_of_precision_from_geometry(
    const Eigen::Vector3d& receiver_ecef_m, const Eigen::MatrixX4d& geometry);

}  // namespace fedsim::nav
