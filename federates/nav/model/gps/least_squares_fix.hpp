// The single-epoch position and clock solution from pseudoranges (seed 6.11; Misra & Enge,
// Global Positioning System, 2nd ed. 2006, ch. 6): iterated linearised least squares
// (Gauss-Newton) for x = (r_ecef, b = c dt),
//   rho_hat_k = |s_k - r| + b,   H_k = [-(s_k - r)^T / |s_k - r|, 1],
//   dx = (H^T H)^-1 H^T (rho - rho_hat),   x <- x + dx,
// from a starting point (the earth's centre with zero clock when nothing better is known, or
// the last fix), until |dx| < convergence_m. Four or more pseudoranges are needed; with exactly
// four the solution fits them exactly. DOPs come from the final H (dilution_of_precision.hpp).
#pragma once

#include "federates/nav/model/gps/dilution_of_precision.hpp"
#include "federates/nav/model/gps/pseudorange_model.hpp"

#include <Eigen/Core>

#include <vector>

namespace fedsim::nav {

enum class FixStatus {
  kValid,
  kDenied,              // the receiver was told GPS is denied (jammed, switched off, failed)
  kTooFewSatellites,    // fewer than 4 pseudoranges
  kSingularGeometry,    // H^T H not invertible (e.g. satellites in a line)
  kNotConverged,        // Gauss-Newton did not converge in max_iterations
};
const char* to_string(FixStatus status);

struct LeastSquaresSettings {
  int max_iterations = 20;
  double convergence_m = 1e-4;  // |dx| below which the iteration stops [m]
};

struct LeastSquaresFix {
  FixStatus status = FixStatus::kTooFewSatellites;
  Eigen::Vector3d position_ecef_m = Eigen::Vector3d::Zero();
  double clock_bias_m = 0.0;        // c dt [m]
  int iterations = 0;
  double residual_rms_m = 0.0;      // RMS of rho - rho_hat at the solution [m]
  DilutionOfPrecision dop;
};

/// Solves for position and clock; never throws for geometry, reports it in status. Throws
/// std::invalid_argument for non-finite inputs.
LeastSquaresFix solve_least_squares(const std::vector<Pseudorange>& pseudoranges,
                                    const Eigen::Vector3d& initial_position_ecef_m,
                                    double initial_clock_bias_m,
                                    const LeastSquaresSettings& settings = {});

}  // namespace fedsim::nav
