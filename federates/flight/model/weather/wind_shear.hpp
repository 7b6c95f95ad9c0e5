// Microburst wind shear: the Oseguera-Bowles analytic downburst model (NASA TM-100632).
#pragma once

#include <Eigen/Core>

namespace fedsim::flight {

/// Axisymmetric microburst (downburst) after R. M. Oseguera and R. L. Bowles, "A Simple,
/// Analytic 3-Dimensional Downburst Model Based on Boundary Layer Stagnation Flow",
/// NASA TM-100632, 1988 (executive step 2, added to the steady wind).
///
/// Inputs:  the point's north / east position (m, in the NED frame the burst's centre is given
///          in) and its height above the ground (m).
/// Output:  wind_ned_mps, the air velocity in NED (m/s).
///
/// With r the distance from the burst axis and z the height (up):
///   u(r, z) = lambda R^2 / (2 r) [1 - exp(-(r/R)^2)] [exp(-z/z*) - exp(-z/eps)]   (outward)
///   w(r, z) = -lambda exp(-(r/R)^2) [eps (exp(-z/eps) - 1) - z* (exp(-z/z*) - 1)]  (up)
/// R: downdraft radius; z*: height scale of the outflow out of the boundary layer; eps: height
/// scale inside it (z* > eps). The flow is incompressible (div = 0) and vanishes at the
/// ground. The strongest outflow is at r = 1.1209 R and z_m = ln(z*/eps) z* eps / (z* - eps);
/// lambda is set from the pack's peak outflow speed there. The core downdraft aloft is
/// lambda (z* - eps). A burst with max_outflow_mps = 0 is calm.
class WindShear {
 public:
  struct Params {
    double centre_north_m = 0.0;
    double centre_east_m = 0.0;
    double downdraft_radius_m = 1000.0;           ///< R
    double max_outflow_mps = 0.0;                 ///< peak radial outflow speed (0: no burst)
    double outflow_height_scale_m = 200.0;        ///< z*
    double boundary_layer_height_scale_m = 30.0;  ///< eps (< z*)

    /// Throws std::invalid_argument naming the bad field.
    void validate() const;
  };

  WindShear() = default;  ///< calm
  explicit WindShear(Params params);

  Eigen::Vector3d wind_ned_mps(double north_m, double east_m, double height_agl_m) const;

  /// Height (m) and radius (m) of the strongest outflow, and the core downdraft (m/s, > 0
  /// for downward) well above the outflow.
  double peak_outflow_height_m() const { return peak_height_m_; }
  double peak_outflow_radius_m() const;
  double core_downdraft_mps() const;
  const Params& params() const { return params_; }

 private:
  double vertical_profile(double height_m) const;  // exp(-z/z*) - exp(-z/eps)

  Params params_;
  double lambda_per_s_ = 0.0;
  double peak_height_m_ = 0.0;
};

}  // namespace fedsim::flight
