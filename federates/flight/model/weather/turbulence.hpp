// Dryden continuous turbulence per MIL-F-8785C: gust velocities and gust rotation rates from
// seeded white noise through exactly discretised shaping filters.
#pragma once

#include <Eigen/Core>
#include <cstdint>
#include <random>

#include "common/math/interpolation.hpp"

namespace fedsim::flight {

/// Dryden turbulence, MIL-F-8785C section 3.7 (executive step 2, added to the steady wind).
///
/// Inputs:  true airspeed (m/s), height above ground (m), NED-to-body DCM, the mean (steady)
///          wind in NED (m/s, sets the low-altitude turbulence axes).
/// Outputs: gust velocity of the air in NED and in body axes (m/s); gust rotation rates
///          (p_g, q_g, r_g) in body axes (rad/s); the scale lengths and intensities used.
///
/// Spectra (Omega spatial frequency, L scale length, sigma intensity):
///   Phi_u = sigma_u^2 (2 L_u / pi) / (1 + (L_u Omega)^2)
///   Phi_v,w = sigma^2 (L / pi) (1 + 3 (L Omega)^2) / (1 + (L Omega)^2)^2
/// realised in time through Taylor's frozen-field hypothesis (tau = L / V) by a first-order
/// filter for u and a double-pole filter with zero at 1 / (sqrt 3 tau) for v and w. Each is
/// discretised exactly (state transition and noise covariance of the continuous process over
/// the step, Cholesky-factored), so the output has the Dryden variance and autocorrelation
///   R_u = sigma^2 exp(-xi / L),   R_v,w = sigma^2 (1 - xi / (2 L)) exp(-xi / L)
/// at any step size. States are kept normalised, so intensity and scale length may change
/// with height without transients.
///
/// Gust rates (MIL-F-8785C; Etkin's definitions p_g = dw_g/dy, q_g = -dw_g/dx,
/// r_g = dv_g/dx; the aerodynamics should use body rates minus gust rates):
///   H_p = sigma_w sqrt(0.8 / V) (pi / 4b)^(1/6) / (L_w^(1/3) (1 + 4b s / (pi V)))  (own noise)
///   H_q = -(s / V) / (1 + 4b s / (pi V)) H_w,   H_r = (s / V) / (1 + 3b s / (pi V)) H_v.
///
/// Scale lengths and intensities (h above ground, in feet as in the standard):
///   below 1000 ft: L_w = h, L_u = L_v = h / (0.177 + 0.000823 h)^1.2, sigma_w = 0.1 W20,
///                  sigma_u = sigma_v = sigma_w / (0.177 + 0.000823 h)^0.4, h >= 10 ft;
///                  axes: u along the mean wind (horizontal), w down (NED vertical);
///   above 2000 ft: L = 1750 ft, sigma_u = sigma_v = sigma_w from the probability-of-exceedance
///                  curves of MIL-F-8785C figure 7; axes: body;
///   in between:    scale lengths, intensities and the NED gust vectors interpolated linearly.
/// W20 is the wind speed at 20 ft (light 15 kt, moderate 30 kt, severe 45 kt).
/// Random numbers: std::mt19937_64 seeded with Params::seed, std::normal_distribution; the
/// same seed gives the same sequence (for a given standard library). No allocation per step.
class Turbulence {
 public:
  enum class Severity { kNone, kLight, kModerate, kSevere };

  struct Params {
    double w20_mps = 0.0;  ///< wind speed at 20 ft (6.096 m), sets low-altitude sigma
    /// MIL-F-8785C figure 7 curve: 0 none; 1: 1e-1, 2: 1e-2 (light), 3: 2e-3, 4: 1e-3
    /// (moderate), 5: 1e-4, 6: 1e-5 (severe), 7: 1e-6 probability of exceedance.
    int exceedance_curve = 0;
    double wingspan_m = 10.0;
    std::uint64_t seed = 1;

    /// Throws std::invalid_argument naming the bad field.
    void validate() const;
    /// MIL-F-8785C's light / moderate / severe: W20 15 / 30 / 45 kt, curves 2 / 4 / 6.
    static Params for_severity(Severity severity, double wingspan_m, std::uint64_t seed);
  };

  struct Inputs {
    double tas_mps = 0.0;
    double height_agl_m = 0.0;
    Eigen::Matrix3d body_from_ned = Eigen::Matrix3d::Identity();
    Eigen::Vector3d mean_wind_ned_mps = Eigen::Vector3d::Zero();
  };

  struct Scales {
    double length_u_m = 0.0, length_v_m = 0.0, length_w_m = 0.0;
    double sigma_u_mps = 0.0, sigma_v_mps = 0.0, sigma_w_mps = 0.0;
  };

  struct Outputs {
    Eigen::Vector3d gust_ned_mps = Eigen::Vector3d::Zero();
    Eigen::Vector3d gust_body_mps = Eigen::Vector3d::Zero();
    Eigen::Vector3d gust_rates_body_radps = Eigen::Vector3d::Zero();  ///< p_g, q_g, r_g
    Scales scales;
  };

  explicit Turbulence(Params params);

  /// Re-seeds the generator and draws the filter states from their stationary distribution.
  void reset();
  void step(double dt_s, const Inputs& in);

  const Outputs& outputs() const { return outputs_; }
  const Params& params() const { return params_; }

  /// Scale lengths and intensities at a height above ground.
  Scales scales(double height_agl_m) const;
  /// Intensity of the roll gust rate p_g for a vertical intensity and scale (rad/s).
  double roll_rate_sigma_radps(double sigma_w_mps, double length_w_m) const;

 private:
  struct FilterSample {
    double u, v, w;  // unit-variance Dryden samples
  };
  FilterSample advance_filters(double dt_s, double tas_mps, const Scales& s);
  Eigen::Vector3d to_ned(const Eigen::Vector3d& uvw, const Inputs& in) const;

  Params params_;
  Table1D high_altitude_sigma_;  // MIL-F-8785C fig. 7 curve: height (m) -> sigma (m/s)
  std::mt19937_64 rng_;
  std::normal_distribution<double> normal_;
  double y_u_ = 0.0;
  double y_v_[2] = {0.0, 0.0};
  double y_w_[2] = {0.0, 0.0};
  double y_p_ = 0.0;
  double lag_v_mps_ = 0.0;  // v_g low-passed over 3b / (pi V), for r_g
  double lag_w_mps_ = 0.0;  // w_g low-passed over 4b / (pi V), for q_g
  bool lags_primed_ = false;
  Outputs outputs_;
};

}  // namespace fedsim::flight
