// Aerodynamic coefficient build-up (seed 3.3-3.4, eqs 3.19-3.21) from an aircraft pack's terms.
#pragma once

#include <Eigen/Dense>
#include <array>
#include <cstddef>
#include <limits>

#include "flight/model/aircraft/aero_flow_envelope.hpp"
#include "flight/model/aircraft/aero_variable.hpp"
#include "flight/model/aircraft/aircraft_pack.hpp"

namespace fedsim::flight {

/// Sums each axis's terms into coefficients, then forms forces and moments:
///   L = qbar S CL, D = qbar S CD, Y = qbar S CY   (wind axes: -z_w, -x_w, +y_w),
///   moments = qbar S [b Cl, c Cm, b Cn]           (body axes, about the aero reference point).
/// Rate terms use the non-dimensional rates p_hat = p b / 2V etc., so Cl_p * p_hat is the
/// book's 1/4 rho V S b^2 Cl_p p term (eq. 3.19). The wind-axis forces are turned into body
/// axes with alpha and beta. Evaluation neither allocates nor throws.
///
/// Flow beyond the pack's data (AeroFlowEnvelope: a tailwind, a crosswind, a deep stall):
/// the terms are summed with alpha and beta held at the envelope's edge, and the result is
/// weighted by the envelope's attached_weight w (1 inside the data). The remaining 1 - w is
/// separated flow: no lift or side force, and the pack's drag (along the air-relative
/// velocity) and moments evaluated at the wing-plane incidence asin(w/V), which is defined and
/// continuous for every flow direction (beta held in the envelope):
///   CL = w CL_pack(alpha, beta), CY = w CY_pack(alpha, beta),
///   CD, Cl, Cm, Cn = w C_pack(alpha, beta) + (1 - w) C_pack(asin(w/V), beta).
/// So a flat-falling aircraft keeps its nose-down pitching moment and a parked one its
/// weathercock yaw, while a tailwind (alpha near 180 deg) gives about the head-on drag and
/// pitching moment instead of an extrapolated CL of -14. Inside the envelope the result is
/// exactly the pack's build-up.
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
    Eigen::Vector3d omega_air_body = Eigen::Vector3d::Zero();  // p, q, r relative to the air, rad/s
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
    Eigen::Vector3d force_body = Eigen::Vector3d::Zero();      // N, body axes
    Eigen::Vector3d moment_body = Eigen::Vector3d::Zero();     // N m, body axes, about the aero RP
    bool stall_hysteresis = false;                          // the flag used for this result
    double attached_weight = 1.0;  // share of the pack's build-up (1 inside its data)
  };

  explicit Aerodynamics(const AircraftPack& pack);
  Aerodynamics(const AeroModelSpec& model, const aircraft_pack::ReferenceGeometry& geometry,
               double flap_full_travel_rad);

  /// Clears the stall-hysteresis flag.
  void reset() { stalled_ = false; }

  /// Updates the stall-hysteresis flag from alpha (if the pack has one; a flow from behind
  /// counts by its forward-equivalent alpha), then computes.
  Outputs evaluate(const Inputs& in);

  /// Pure computation with a given hysteresis flag (for trim and linearisation).
  Outputs compute(const Inputs& in, bool stall_hysteresis) const;

  bool stall_hysteresis_active() const { return stalled_; }
  const aircraft_pack::ReferenceGeometry& geometry() const { return geometry_; }
  const AeroModelSpec& model() const { return model_; }
  /// The flow angles the pack's data cover.
  const AeroFlowEnvelope& envelope() const { return envelope_; }

  /// Direction cosine matrix turning wind-axis vectors into body axes.
  static Eigen::Matrix3d body_from_wind(double alpha_rad, double beta_rad);

 private:
  static constexpr std::size_t kSlotCount = kAeroVariableCount + AeroModelSpec::kMaxFactors;
  using Slots = std::array<double, kSlotCount>;

  /// The slots for the inputs, with these flow angles in place of the inputs' own.
  void fill_variables(const Inputs& in, double alpha_rad, double beta_rad, bool stall_hysteresis,
                      Slots& slots) const;
  double sum_axis(AeroAxis axis, const Slots& slots) const;
  /// The six coefficients of the pack's build-up at these flow angles (into out.CL ... Cn).
  void sum_coefficients(const Inputs& in, double alpha_rad, double beta_rad,
                        bool stall_hysteresis, Outputs& out) const;
  /// Weights the attached-flow coefficients in `out` by w and adds separated-flow drag.
  void blend_separated_flow(const Inputs& in, bool stall_hysteresis, double w,
                            Outputs& out) const;

  AeroModelSpec model_;
  aircraft_pack::ReferenceGeometry geometry_;
  double flap_full_travel_deg_ = 0.0;
  AeroFlowEnvelope envelope_;
  bool stalled_ = false;
};

}  // namespace fedsim::flight
