// Naturally aspirated piston engine: manifold pressure, shaft torques, power and fuel flow.
#include "flight/model/systems/piston_engine.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "flight/model/systems/param_checks.hpp"

namespace fedsim::flight {

namespace {
constexpr double kSeaLevelPressurePa = 101325.0;  // ISA sea level (US Standard Atmosphere 1976)
constexpr double kSeaLevelTemperatureK = 288.15;
constexpr double kSeaLevelDensityKgpm3 = 1.225;
constexpr double kRevolutionsPerCycle = 2.0;  // four-stroke
constexpr double kLowestRpm = 1.0;            // keeps N_idle / N finite at a standstill
// Specific heats at constant pressure (J/(kg K)) of air and of fuel vapour, as JSBSim's
// FGPiston uses them in its exhaust energy balance.
constexpr double kCpAirJpkgk = 1005.0;
constexpr double kCpFuelJpkgk = 1700.0;

double clamp01(double x) { return std::isnan(x) ? 0.0 : std::clamp(x, 0.0, 1.0); }

// Shaft power (W) of a torque at a given speed.
double power_w(double torque_nm, double rpm) {
  return torque_nm * rpm * 2.0 * std::numbers::pi / 60.0;
}
}  // namespace

Table1D PistonEngine::Params::default_mixture_efficiency() {
  // Fuel/air mass ratio -> power factor. D. Luff's correlation, as tabulated in JSBSim's
  // FGPiston (public domain figures for a Lycoming-class engine).
  return Table1D({0.05000, 0.05137, 0.05179, 0.05430, 0.05842, 0.06312, 0.06942, 0.07786, 0.08845,
                  0.09270, 0.10120, 0.11455, 0.12158, 0.12435, 0.12500},
                 {0.00000, 0.00862, 0.21552, 0.48276, 0.70690, 0.83621, 0.93103, 1.00000, 1.00000,
                  0.98276, 0.93103, 0.72414, 0.45690, 0.23276, 0.00000});
}

Table1D PistonEngine::Params::default_combustion_efficiency() {
  // Equivalence ratio -> combustion efficiency, as tabulated in JSBSim's FGPiston (rich
  // mixtures leave unburnt fuel: 0.70 at phi = 1.3).
  return Table1D({0.00, 0.90, 1.00, 1.05, 1.10, 1.15, 1.20, 1.30, 1.40, 1.50, 1.60, 2.00},
                 {0.980, 0.980, 0.970, 0.950, 0.900, 0.850, 0.790, 0.700, 0.630, 0.570, 0.525,
                  0.345});
}

void PistonEngine::Params::validate() const {
  namespace pc = param_checks;
  pc::positive(rated_power_w, "rated_power_w");
  pc::positive(rated_rpm, "rated_rpm");
  pc::positive(idle_rpm, "idle_rpm");
  if (!(idle_rpm < rated_rpm)) pc::fail("idle_rpm", "must be below rated_rpm", idle_rpm);
  pc::positive(displacement_m3, "displacement_m3");
  pc::non_negative(intake_loss_pa_per_rpm, "intake_loss_pa_per_rpm");
  const double rated_map = kSeaLevelPressurePa - intake_loss_pa_per_rpm * rated_rpm;
  if (!(rated_map > 0.5 * kSeaLevelPressurePa)) {
    pc::fail("intake_loss_pa_per_rpm", "leaves under half an atmosphere at rated rpm",
             intake_loss_pa_per_rpm);
  }
  pc::positive(idle_manifold_pressure_pa, "idle_manifold_pressure_pa");
  if (!(idle_manifold_pressure_pa < rated_map)) {
    pc::fail("idle_manifold_pressure_pa", "must be below the full-throttle MAP",
             idle_manifold_pressure_pa);
  }
  pc::non_negative(fmep_pa, "fmep_pa");
  pc::non_negative(fmep_per_krpm_pa, "fmep_per_krpm_pa");
  pc::non_negative(fmep_per_krpm2_pa, "fmep_per_krpm2_pa");
  pc::positive(bsfc_kgpj, "bsfc_kgpj");
  pc::positive(best_power_fuel_air_ratio, "best_power_fuel_air_ratio");
  pc::positive(full_rich_fuel_air_ratio, "full_rich_fuel_air_ratio");
  pc::in_range(idle_cutoff_mixture, 0.0, 0.5, "idle_cutoff_mixture");
  pc::not_empty(mixture_efficiency, "mixture_efficiency");
  pc::positive(fuel_heating_value_jpkg, "fuel_heating_value_jpkg");
  pc::in_range(exhaust_heat_fraction, 0.0, 1.0, "exhaust_heat_fraction");
  pc::in_range(stoichiometric_fuel_air_ratio, 0.01, 0.2, "stoichiometric_fuel_air_ratio");
  pc::not_empty(combustion_efficiency, "combustion_efficiency");
  for (double eta : combustion_efficiency.values()) {
    pc::in_range(eta, 0.0, 1.0, "combustion_efficiency");
  }
  const double best = mixture_efficiency(best_power_fuel_air_ratio);
  if (!(best > 0.0)) {
    pc::fail("best_power_fuel_air_ratio", "has zero mixture efficiency", best_power_fuel_air_ratio);
  }
}

PistonEngine::PistonEngine(Params params) : params_(std::move(params)) {
  params_.validate();
  const Params& p = params_;
  rated_map_pa_ = kSeaLevelPressurePa - p.intake_loss_pa_per_rpm * p.rated_rpm;
  // Rated point: brake MEP from rated power, plus the pumping and friction losses there,
  // divided by the mixture efficiency at best power (normally 1).
  const double rated_bmep_pa =
      p.rated_power_w * 60.0 * kRevolutionsPerCycle / (p.displacement_m3 * p.rated_rpm);
  const double rated_pmep_pa = kSeaLevelPressurePa - rated_map_pa_;
  rated_imep_pa_ = (rated_bmep_pa + rated_pmep_pa + friction_mep_pa(p.rated_rpm)) /
                   p.mixture_efficiency(p.best_power_fuel_air_ratio);
  rated_air_flow_kgps_ = p.bsfc_kgpj * p.rated_power_w / p.best_power_fuel_air_ratio;
}

double PistonEngine::friction_mep_pa(double rpm) const {
  const double krpm = std::max(rpm, 0.0) / 1000.0;
  return params_.fmep_pa + params_.fmep_per_krpm_pa * krpm +
         params_.fmep_per_krpm2_pa * krpm * krpm;
}

double PistonEngine::mep_to_torque_nm(double mep_pa) const {
  return mep_pa * params_.displacement_m3 / (2.0 * std::numbers::pi * kRevolutionsPerCycle);
}

double PistonEngine::manifold_pressure_pa(const Inputs& in) const {
  const double rpm = std::max(in.engine_rpm, 0.0);
  const double p_amb = std::max(in.ambient_pressure_pa, 0.0);
  const double full_throttle = std::max(p_amb - params_.intake_loss_pa_per_rpm * rpm, 0.0);
  const double closed_throttle =
      std::min(full_throttle, params_.idle_manifold_pressure_pa * (p_amb / kSeaLevelPressurePa) *
                                  (params_.idle_rpm / std::max(rpm, kLowestRpm)));
  return closed_throttle + clamp01(in.throttle) * (full_throttle - closed_throttle);
}

double PistonEngine::fuel_air_ratio(const Inputs& in) const {
  const double ml = clamp01(in.mixture);
  const double density_ratio = std::max(in.ambient_density_kgpm3, 1e-6) / kSeaLevelDensityKgpm3;
  return params_.full_rich_fuel_air_ratio / (2.0 - ml * ml) / std::sqrt(density_ratio);
}

double PistonEngine::exhaust_gas_temperature_k(const Outputs& out, double ambient_k) const {
  // Energy balance of the exhaust (JSBSim FGPiston::doEGT): heat released into the exhaust
  // over the heat capacity rate of the exhaust stream (air plus fuel).
  const Params& p = params_;
  const bool combusting = out.fuel_flow_kgps > 0.0 && out.air_flow_kgps > 0.0 &&
                          out.mixture_efficiency > 0.0;
  if (!combusting) return ambient_k;
  const double phi = out.fuel_air_ratio / p.stoichiometric_fuel_air_ratio;
  const double heat_w = out.fuel_flow_kgps * p.fuel_heating_value_jpkg *
                        p.combustion_efficiency(phi) * p.exhaust_heat_fraction;
  const double capacity_wpk = kCpAirJpkgk * out.air_flow_kgps + kCpFuelJpkgk * out.fuel_flow_kgps;
  return ambient_k + heat_w / capacity_wpk;
}

PistonEngine::Outputs PistonEngine::evaluate(const Inputs& in) const {
  Outputs out;
  const double rpm = std::max(in.engine_rpm, 0.0);
  out.manifold_pressure_pa = manifold_pressure_pa(in);

  // Charge density relative to the rated point (SAE J1349 temperature correction).
  const double temperature_k = std::max(in.ambient_temperature_k, 1.0);
  const double charge =
      (out.manifold_pressure_pa / rated_map_pa_) * std::sqrt(kSeaLevelTemperatureK / temperature_k);

  const bool burning =
      in.running && !in.failed && !(clamp01(in.mixture) < params_.idle_cutoff_mixture);
  out.air_flow_kgps = rated_air_flow_kgps_ * charge * (rpm / params_.rated_rpm);
  if (burning) {
    out.fuel_air_ratio = fuel_air_ratio(in);
    out.mixture_efficiency = params_.mixture_efficiency(out.fuel_air_ratio);
    out.fuel_flow_kgps = out.fuel_air_ratio * out.air_flow_kgps;
  }
  out.exhaust_gas_temperature_k = exhaust_gas_temperature_k(out, temperature_k);
  const double imep_pa = burning ? rated_imep_pa_ * charge * out.mixture_efficiency : 0.0;
  const double pumping_mep_pa = std::max(in.ambient_pressure_pa - out.manifold_pressure_pa, 0.0);

  out.combustion_torque_nm = mep_to_torque_nm(imep_pa);
  out.loss_torque_nm = mep_to_torque_nm(pumping_mep_pa + friction_mep_pa(rpm));
  out.brake_torque_nm = out.combustion_torque_nm - out.loss_torque_nm;
  out.brake_power_w = power_w(out.brake_torque_nm, rpm);
  return out;
}

}  // namespace fedsim::flight
