// Gauss-Newton position and clock solution.
#include "federates/nav/model/gps/least_squares_fix.hpp"

#include <Eigen/Dense>

#include <cmath>
#include <stdexcept>

namespace fedsim::nav {

namespace {

struct Linearisation {
  Eigen::MatrixX4d geometry;
  Eigen::VectorXd residual_m;
};

Linearisation linearise(const std::vector<Pseudorange>& pseudoranges,
                        const Eigen::Vector3d& position_ecef_m, double clock_bias_m) {
  const auto n = static_cast<Eigen::Index>(pseudoranges.size());
  Linearisation lin{Eigen::MatrixX4d(n, 4), Eigen::VectorXd(n)};
  for (Eigen::Index k = 0; k < n; ++k) {
    const Pseudorange& p = pseudoranges[static_cast<std::size_t>(k)];
    const Eigen::Vector3d delta = p.satellite_ecef_m - position_ecef_m;
    const double range_m = delta.norm();
    lin.geometry.row(k) << -delta.transpose() / range_m, 1.0;
    lin.residual_m[k] = p.pseudorange_m - (range_m + clock_bias_m);
  }
  return lin;
}

}  // namespace

const char* to_string(FixStatus status) {
  switch (status) {
    case FixStatus::kValid: return "valid";
    case FixStatus::kDenied: return "denied";
    case FixStatus::kTooFewSatellites: return "too few satellites";
    case FixStatus::kSingularGeometry: return "singular geometry";
    case FixStatus::kNotConverged: return "not converged";
  }
  return "unknown";
}

LeastSquaresFix solve_least_squares(const std::vector<Pseudorange>& pseudoranges,
                                    const Eigen::Vector3d& initial_position_ecef_m,
                                    double initial_clock_bias_m,
                                    const LeastSquaresSettings& settings) {
  if (!initial_position_ecef_m.allFinite() || !std::isfinite(initial_clock_bias_m)) {
    throw std::invalid_argument("solve_least_squares: the starting point is not finite");
  }
  if (settings.max_iterations < 1 || !std::isfinite(settings.convergence_m) ||
      settings.convergence_m <= 0.0) {
    throw std::invalid_argument("solve_least_squares: settings out of range");
  }
  for (const Pseudorange& p : pseudoranges) {
    if (!p.satellite_ecef_m.allFinite() || !std::isfinite(p.pseudorange_m)) {
      throw std::invalid_argument("solve_least_squares: a pseudorange or satellite position is "
                                  "not finite");
    }
  }
  LeastSquaresFix fix;
  if (pseudoranges.size() < 4) return fix;  // kTooFewSatellites

  Eigen::Vector3d position = initial_position_ecef_m;
  double clock_m = initial_clock_bias_m;
  fix.status = FixStatus::kNotConverged;
  for (int iteration = 1; iteration <= settings.max_iterations; ++iteration) {
    const Linearisation lin = linearise(pseudoranges, position, clock_m);
    const std::optional<Eigen::Matrix4d> inverse =
        inverse_of_normal_matrix(lin.geometry.transpose() * lin.geometry);
    if (!inverse) {
      fix.status = FixStatus::kSingularGeometry;
      return fix;
    }
    const Eigen::Vector4d dx = *inverse * (lin.geometry.transpose() * lin.residual_m);
    position += dx.head<3>();
    clock_m += dx[3];
    fix.iterations = iteration;
    if (dx.norm() < settings.convergence_m) {
      fix.status = FixStatus::kValid;
      break;
    }
  }
  if (fix.status != FixStatus::kValid) return fix;

  const Linearisation final_lin = linearise(pseudoranges, position, clock_m);
  const std::optional<DilutionOfPrecision> dop =
      dilution_of_precision_from_geometry(position, final_lin.geometry);
  if (!dop) {
    fix.status = FixStatus::kSingularGeometry;
    return fix;
  }
  fix.position_ecef_m = position;
  fix.clock_bias_m = clock_m;
  fix.residual_rms_m =
      std::sqrt(final_lin.residual_m.squaredNorm() / static_cast<double>(pseudoranges.size()));
  fix.dop = *dop;
  return fix;
}

}  // namespace fedsim::nav
