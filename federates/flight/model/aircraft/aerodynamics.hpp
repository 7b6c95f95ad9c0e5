// Aerodynamic coefficient build-up (seed 3.3-3.4, eqs 3.19-3.21) from an aircraft pack's terms.
#pragma once

#include <Eigen/Dense>
#include <array>
#include <cstddef>
#include <limits>

#include "flight/model/aircraft/aero_variable.hpp"
#include "flight/model/aircraft/aircraft_pack.hpp"

namespace fedsim::flight {

/// Sums each axis's terms into coefficients, then forms forces and moments:
///   L = qbar S CL, D = qbar S CD, Y = qbar S CY   (wind axes: -z_w, -x_w, +y_w),
///   moments = qbar S [b Cl, c Cm, b Cn]           (body axes, about the aero reference point).
/// Rate terms use the non-dimensional rates p_hat = p b / 2V etc., so Cl_p * p_hat is the
/// book's 1/4 rho V S b^2 Cl_p p term (eq. 3.19). The wind-axis forces are turned into body
/// axes with alpha and beta. Evaluation neither allocates nor throws.
class Aerodynamics {
 public:
  /// Below this airspeed the non-dimensional rates are taken as zero (their terms vanish with
  /// V anyway: qbar * p b / 2V is proportional to V).
  static constexpr double kMinAirspeedForRatesMps = 1e-3;

  struct Inputs {
    double alpha_rad = 0.0;
    double beta_rad = 0.0;
    double tas_mps = 0.0;
    double mach = 0.0;
    double qbar_pa = 0.0;
    Eigen::Vector3d omega_air_b = Eigen::Vector3d::Zero();  // p, q, r relative to the air, rad/s
    double alphadot_radps = 0.0;
    double betadot_radps = 0.0;
    double elevator_rad = 0.0;    // trailing edge down positive
    double aileron_rad = 0.0;     // right-wing-down rolling positive
    double rudder_rad = 0.0;      // trailing edge left positive
    double flap_norm = 0.0;       // 0..1 of full flap travel
    double gear_norm = 0.0;       // 0 up .. 1 down
    double speedbrake_norm = 0.0;
    double spoiler_norm = 0.0;
    /// Height of the aero reference point above the ground (for ground effect); the default
    /// is far out of ground effect.
    double aero_rp_height_agl_m = 1e6;
  };

  struct Outputs {
    // Coefficients (standard notation: CL lift, Cl rolling moment).
    double CL = 0.0, CD = 0.0, CY = 0.0;
    double Cl = 0.0, Cm = 0.0, Cn = 0.0;
    double lift_n = 0.0, drag_n = 0.0, side_force_n = 0.0;  // wind axes
    Eigen::Vector3d force_b = Eigen::Vector3d::Zero();      // N, body axes
    Eigen::Vector3d moment_b = Eigen::Vector3d::Zero();     // N m, body axes, about the aero RP
    bool stall_hysteresis = false;                          // the flag used for this result
  };

  explicit Aerodynamics(const AircraftPack& pack);
  Aerodynamics(const AeroModelSpec& model, const ReferenceGeometry& geometry,
               double flap_full_travel_rad);

  /// Clears the stall-hysteresis flag.
  void reset() { stalled_ = false; }

  /// Updates the stall-hysteresis flag from alpha (if the pack has one), then computes.
  Outputs evaluate(const Inputs& in);

  /// Pure computation with a given hysteresis flag (for trim and linearisation).
  Outputs compute(const Inputs& in, bool stall_hysteresis) const;

  bool stall_hysteresis_active() const { return stalled_; }
  const ReferenceGeometry& geometry() const { return geometry_; }
  const AeroModelSpec& model() const { return model_; }

  /// Direction cosine matrix turning wind-axis vectors into body axes.
  static Eigen::Matrix3d wind_to_body(double alpha_rad, double beta_rad);

 private:
  static constexpr std::size_t kSlotCount = kAeroVariableCount + AeroModelSpec::kMaxFactors;
  using Slots = std::array<double, kSlotCount>;

  void fill_variables(const Inputs& in, bool stall_hysteresis, Slots& slots) const;
  double sum_axis(AeroAxis axis, const Slots& slots) const;

  AeroModelSpec model_;
  ReferenceGeometry geometry_;
  double flap_full_travel_deg_ = 0.0;
  bool stalled_ = false;
};

}  // namespace fedsim::flight
