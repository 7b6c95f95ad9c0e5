// Propeller aerodynamics: thrust and absorbed torque from CT / CP tables of advance ratio
// and blade angle.
#include "flight/model/systems/propeller.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>

#include "flight/model/systems/param_checks.hpp"

namespace fedsim::flight {

namespace {
constexpr double kLargestReportedAdvanceRatio = 1000.0;  // J of a stopped propeller in a wind

void check_coefficient_table(const Table2D& table, const std::string& field) {
  param_checks::not_empty(table, field);
  if (table.rows().front() < 0.0) {
    throw std::invalid_argument(field + ": advance ratios must start at or above 0");
  }
  if (!(table.rows().back() > 0.0)) {
    throw std::invalid_argument(field + ": needs an advance ratio above 0");
  }
}

double factor_or_one(const Table1D& table, double x) { return table.empty() ? 1.0 : table(x); }
}  // namespace

void Propeller::Params::validate() const {
  param_checks::positive(diameter_m, "diameter_m");
  check_coefficient_table(thrust_coefficient, "thrust_coefficient");
  check_coefficient_table(power_coefficient, "power_coefficient");
  param_checks::in_range(thrust_coefficient_factor, kMinCoefficientFactor, kMaxCoefficientFactor,
                         "thrust_coefficient_factor");
  param_checks::in_range(power_coefficient_factor, kMinCoefficientFactor, kMaxCoefficientFactor,
                         "power_coefficient_factor");
  if (factor_fade) {
    param_checks::in_range(factor_fade->start_advance_ratio, 0.0, kMaxFadeAdvanceRatio,
                           "factor_fade_start_advance_ratio");
    param_checks::in_range(factor_fade->end_advance_ratio, 0.0, kMaxFadeAdvanceRatio,
                           "factor_fade_end_advance_ratio");
    if (!(factor_fade->end_advance_ratio > factor_fade->start_advance_ratio)) {
      param_checks::fail("factor_fade_end_advance_ratio",
                         "must exceed factor_fade_start_advance_ratio (" +
                             std::to_string(factor_fade->start_advance_ratio) + ")",
                         factor_fade->end_advance_ratio);
    }
  }
}

Propeller::Propeller(Params params) : params_(std::move(params)) { params_.validate(); }

double Propeller::thrust_coefficient(double advance_ratio, double blade_angle_rad) const {
  return params_.thrust_coefficient(advance_ratio, blade_angle_rad);
}

double Propeller::power_coefficient(double advance_ratio, double blade_angle_rad) const {
  return params_.power_coefficient(advance_ratio, blade_angle_rad);
}

double Propeller::correction_weight(double advance_ratio) const {
  if (!params_.factor_fade) return 1.0;
  const double start = params_.factor_fade->start_advance_ratio;
  const double end = params_.factor_fade->end_advance_ratio;
  return std::clamp((end - advance_ratio) / (end - start), 0.0, 1.0);
}

double Propeller::thrust_coefficient_factor_at(double advance_ratio) const {
  return 1.0 + (params_.thrust_coefficient_factor - 1.0) * correction_weight(advance_ratio);
}

double Propeller::power_coefficient_factor_at(double advance_ratio) const {
  return 1.0 + (params_.power_coefficient_factor - 1.0) * correction_weight(advance_ratio);
}

double Propeller::dimensional(const Table2D& table, double blade_angle_rad, double rps,
                              double airspeed_mps, double density_kgpm3, int diameter_power) const {
  const double d = params_.diameter_m;
  const double j_end = table.rows().back();
  const double d_k = std::pow(d, diameter_power);
  if (rps * d * j_end >= airspeed_mps && rps > 0.0) {
    const double j = airspeed_mps / (rps * d);
    return table(j, blade_angle_rad) * density_kgpm3 * rps * rps * d_k;
  }
  // Beyond the table: coefficient grows as J^2, so the force depends on V, not on n.
  const double c_end = table(j_end, blade_angle_rad);
  return c_end / (j_end * j_end) * density_kgpm3 * airspeed_mps * airspeed_mps * d_k / (d * d);
}

Propeller::Outputs Propeller::evaluate(const Inputs& in) const {
  Outputs out;
  const double rps = std::isnan(in.rpm) ? 0.0 : std::max(in.rpm, 0.0) / 60.0;
  const double v = std::isnan(in.axial_airspeed_mps) ? 0.0 : std::max(in.axial_airspeed_mps, 0.0);
  const double rho = std::max(in.density_kgpm3, 0.0);
  const double d = params_.diameter_m;
  const double tip_speed = std::numbers::pi * rps * d;

  out.advance_ratio = rps > 0.0 ? std::min(v / (rps * d), kLargestReportedAdvanceRatio)
                                : (v > 0.0 ? kLargestReportedAdvanceRatio : 0.0);
  out.tip_mach = std::hypot(v, tip_speed) / std::max(in.speed_of_sound_mps, 1.0);
  // The factors at the true advance ratio (infinite for a stopped propeller in a wind: past any
  // fade band), also beyond the table's end, where the V^2 extension carries them.
  const double true_j = rps > 0.0 ? v / (rps * d) : (v > 0.0 ? HUGE_VAL : 0.0);
  const double ct_factor = thrust_coefficient_factor_at(true_j) *
                           factor_or_one(params_.thrust_tip_mach_factor, out.tip_mach);
  const double cp_factor = power_coefficient_factor_at(true_j) *
                           factor_or_one(params_.power_tip_mach_factor, out.tip_mach);

  out.thrust_coefficient = thrust_coefficient(out.advance_ratio, in.blade_angle_rad) * ct_factor;
  out.power_coefficient = power_coefficient(out.advance_ratio, in.blade_angle_rad) * cp_factor;
  out.thrust_n =
      dimensional(params_.thrust_coefficient, in.blade_angle_rad, rps, v, rho, 4) * ct_factor;
  out.torque_nm = dimensional(params_.power_coefficient, in.blade_angle_rad, rps, v, rho, 5) *
                  cp_factor / (2.0 * std::numbers::pi);
  out.power_w = out.torque_nm * 2.0 * std::numbers::pi * rps;
  out.efficiency = out.power_w > 0.0 ? std::max(out.thrust_n * v / out.power_w, 0.0) : 0.0;
  return out;
}

}  // namespace fedsim::flight
