// Propeller aerodynamics: thrust and absorbed torque from CT / CP tables of advance ratio
// and blade angle.
#pragma once

#include <optional>

#include "common/math/interpolation.hpp"

namespace fedsim::flight {

/// Propeller thrust and torque from non-dimensional coefficient tables (seed 3.8.1, and the
/// CT(J, beta) table of Example 2.4).
///
/// Inputs:  propeller speed (rpm), airspeed along the propeller axis (m/s, positive when
///          moving forward through the air), air density (kg/m^3), speed of sound (m/s),
///          blade angle (rad).
/// Outputs: advance ratio J = V / (n D), CT, CP, thrust (N, along the axis), torque the air
///          exerts against the rotation (N m; negative when the air drives the propeller),
///          absorbed power (W), efficiency J CT / CP.
///
/// Model (n in rev/s, D diameter):
///   T = CT(J, beta) rho n^2 D^4,   Q = CP(J, beta) rho n^2 D^5 / (2 pi),
/// with CT and CP scaled by the factors (JSBSim's <ct_factor>, <cp_factor>: they match a generic
/// table to one aircraft's published performance) and by the optional helical-tip-Mach factors.
/// Without a fade band the factors f are constant (JSBSim's); with one [J_a, J_b] (fedsim's:
/// a correction of the table at low advance ratio that leaves the rest of it as it is) they
/// apply in full up to J_a and fade linearly to none above:
///   f(J) = f for J <= J_a,   f + (1 - f) (J - J_a) / (J_b - J_a) for J_a < J < J_b,   1 beyond.
/// The tables stop at a
/// largest advance ratio J_end; beyond it (which includes a stopped propeller, J -> infinity)
/// the blades see mostly the free stream, forces scale with V^2, i.e. CT and CP grow as J^2:
///   T = CT(J_end) / J_end^2 rho V^2 D^2,   Q = CP(J_end) / J_end^2 rho V^2 D^3 / (2 pi),
/// which joins the table continuously and stays finite at n = 0 (no NaN at zero rpm).
/// Negative airspeed is treated as zero (the tables start at J = 0).
class Propeller {
 public:
  /// The range accepted for the constant CT and CP factors: wide enough for a per-blade table
  /// scaled by the blade count (JSBSim's Aeromatic writes ct_factor = number of blades), narrow
  /// enough to refuse a typo or a unit slip.
  static constexpr double kMinCoefficientFactor = 0.1;
  static constexpr double kMaxCoefficientFactor = 10.0;
  /// The largest advance ratio a fade band may end at: beyond the working range of any
  /// propeller table (fixed-pitch propellers windmill near J 1-1.5, constant-speed propellers of
  /// fast aircraft work up to about J 3), so a larger figure is a typo or a unit slip.
  static constexpr double kMaxFadeAdvanceRatio = 3.0;

  /// Advance-ratio band over which the CT and CP factors fade out: in full at J <= start,
  /// linearly to none (factor 1) at J = end, none beyond. 0 <= start < end <= kMaxFadeAdvanceRatio.
  struct FactorFade {
    double start_advance_ratio = 0.0;
    double end_advance_ratio = 0.0;
  };

  struct Params {
    double diameter_m = 0.0;
    /// Thrust coefficient CT: rows = advance ratio J (from 0, increasing), columns = blade
    /// angle (rad). A fixed-pitch propeller has one column at its blade angle.
    Table2D thrust_coefficient;
    /// Power coefficient CP, same layout.
    Table2D power_coefficient;
    /// Constant multipliers on the CT and CP tables (JSBSim FGPropeller's CtFactor, CpFactor,
    /// which multiply the table values in Calculate() and GetPowerRequired()). Within
    /// [kMinCoefficientFactor, kMaxCoefficientFactor].
    double thrust_coefficient_factor = 1.0;
    double power_coefficient_factor = 1.0;
    /// Where the two factors fade out; none (the default): they apply at every advance ratio.
    std::optional<FactorFade> factor_fade;
    /// Optional factors on CT and CP as functions of helical tip Mach number; empty = 1.
    Table1D thrust_tip_mach_factor;
    Table1D power_tip_mach_factor;

    void validate() const;
  };

  struct Inputs {
    double rpm = 0.0;
    double axial_airspeed_mps = 0.0;
    double density_kgpm3 = 1.225;
    double speed_of_sound_mps = 340.294;
    double blade_angle_rad = 0.0;
  };

  struct Outputs {
    double advance_ratio = 0.0;
    double thrust_coefficient = 0.0;
    double power_coefficient = 0.0;
    double tip_mach = 0.0;
    double thrust_n = 0.0;
    double torque_nm = 0.0;   ///< air torque opposing rotation
    double power_w = 0.0;     ///< torque * shaft speed
    double efficiency = 0.0;  ///< J CT / CP where CP > 0, else 0
  };

  explicit Propeller(Params params);

  Outputs evaluate(const Inputs& in) const;

  /// CT(J, beta) straight from the table (no factor, J clamped to the table).
  double thrust_coefficient(double advance_ratio, double blade_angle_rad) const;
  double power_coefficient(double advance_ratio, double blade_angle_rad) const;
  /// The CT and CP factors at advance ratio J (the constant factors, faded by factor_fade; no
  /// tip-Mach factor).
  double thrust_coefficient_factor_at(double advance_ratio) const;
  double power_coefficient_factor_at(double advance_ratio) const;
  const Params& params() const { return params_; }

 private:
  // Force or torque scale rho n^2 D^k times a coefficient table, with the V^2 extension
  // beyond the table's last advance ratio.
  double dimensional(const Table2D& table, double blade_angle_rad, double rps, double airspeed_mps,
                     double density_kgpm3, int diameter_power) const;
  // The share of a factor's correction (f - 1) that applies at J: 1 without a fade band.
  double correction_weight(double advance_ratio) const;

  Params params_;
};

}  // namespace fedsim::flight
