// Naturally aspirated piston engine: manifold pressure, shaft torques, power and fuel flow.
#pragma once

#include "common/math/interpolation.hpp"

namespace fedsim::flight {

/// Naturally aspirated four-stroke spark-ignition aircraft engine (seed 3.8.1).
///
/// Stateless: the shaft speed belongs to the powerplant (PistonPowerplant), which integrates
/// the torques returned here against the propeller's.
///
/// Inputs:  engine speed (rpm), throttle and mixture levers (0..1), ambient pressure (Pa),
///          temperature (K) and density (kg/m^3), combustion on/off and failure flags.
/// Outputs: manifold pressure (Pa), fuel/air ratio, torques (N m, on the crankshaft),
///          brake power (W), fuel mass flow (kg/s).
///
/// Model (N = engine rpm, all pressures absolute):
///  - Manifold pressure. Eqs. 3.114-3.115 give MAP = p_amb + (0.04635 tl - 0.0469) N in inHg;
///    at full throttle that is an intake loss MAP_full = p_amb - k_loss N
///    (k_loss = 0.00055 inHg/rpm = 1.8625 Pa/rpm). The book's law reaches zero MAP below
///    ~80 % lever, so part throttle interpolates linearly (as JSBSim's piston model does)
///    between MAP_full and the closed-throttle pressure. A closed throttle passes a choked,
///    nearly constant air mass flow, so the closed-throttle MAP is the pack's idle MAP at idle
///    rpm, scaled by p_amb / p_sl and by N_idle / N (capped at MAP_full).
///  - Indicated mean effective pressure IMEP = IMEP_rated * (MAP / MAP_rated) *
///    sqrt(T_sl / T_amb) * eta_mix(F/A). The temperature term is the SAE J1349 / DIN 70020
///    power correction; eta_mix is the mixture efficiency table.
///  - Losses: pumping MEP = p_amb - MAP; friction MEP = a0 + a1 (N/1000) + a2 (N/1000)^2
///    (the Barnes-Moss form quoted by Heywood, Internal Combustion Engine Fundamentals,
///    1988, ch. 13). Both oppose rotation; the powerplant applies them as such.
///  - Torque = MEP * V_d / (2 pi n_R), n_R = 2 crank revolutions per cycle, so nothing
///    divides by rpm and the engine model is defined at N = 0.
///  - IMEP_rated is fixed so that, at rated rpm, full throttle, sea-level ISA and best-power
///    mixture, brake power equals rated_power_w.
///  - Mixture (eq. 3.116): the metered fuel/air ratio is the full-rich sea-level ratio
///    divided by (2 - ml^2) (the lever acts mostly near its forward end), times
///    sqrt(rho_sl / rho): a pressure-metered fuel system enriches as density falls, which is
///    why pilots lean with altitude. Lever 0 halves the ratio (below the lean limit at low
///    altitude); levers below idle_cutoff_mixture are the idle cut-off detent: no fuel.
///  - Fuel flow = F/A * air mass flow; the air flow scales with MAP, sqrt(T_sl/T) and N from
///    its rated value, which is set by bsfc at the rated point with best-power mixture.
///  - `running` false or `failed` true: no combustion, no fuel; losses remain (a stopped or
///    windmilling engine absorbs power).
///  - Exhaust gas temperature: steady energy balance of the exhaust, as JSBSim's FGPiston
///    (doEGT): a fraction of the fuel's heat of combustion leaves with the exhaust,
///      EGT = T_amb + m_f H eta_c(phi) f_exh / (cp_air m_air + cp_fuel m_f),
///    H the fuel's heating value, eta_c the combustion efficiency at the equivalence ratio
///    phi = (F/A) / (F/A)_stoich, f_exh the exhaust's share of the heat. As m_f = (F/A) m_air,
///    EGT depends on the mixture and the ambient temperature, not on the power: it peaks just
///    rich of stoichiometric (phi 1.05: about 1143 K at sea level, ~1600 F, the "peak EGT"
///    pilots lean to) and falls as the mixture is enriched (full rich: ~1051 K, ~1430 F). Not burning (stopped, cut off, failed, or a mixture
///    outside the misfire limits, eta_mix = 0): ambient temperature. No thermal lag.
class PistonEngine {
 public:
  struct Params {
    double rated_power_w = 0.0;              ///< brake power at rated rpm, full throttle, SL
    double rated_rpm = 0.0;                  ///< engine speed of rated power
    double idle_rpm = 0.0;                   ///< speed at which idle_manifold_pressure_pa holds
    double displacement_m3 = 0.0;            ///< swept volume of all cylinders
    double idle_manifold_pressure_pa = 0.0;  ///< closed-throttle MAP at idle rpm, sea level
    /// Full-throttle intake loss per rpm (eq. 3.114 at tl = 1: 0.00055 inHg/rpm).
    /// From a rated (maximum) MAP: (101325 - maxmp_pa) / rated_rpm.
    double intake_loss_pa_per_rpm = 1.8625;
    /// Friction MEP = fmep_pa + fmep_per_krpm_pa (N/1000) + fmep_per_krpm2_pa (N/1000)^2.
    /// Defaults: Barnes-Moss correlation for SI engines.
    double fmep_pa = 97.0e3;
    double fmep_per_krpm_pa = 15.0e3;
    double fmep_per_krpm2_pa = 5.0e3;
    /// Brake specific fuel consumption at the rated point with best-power mixture, kg/J
    /// (1 lb/(hp h) = 1.68966e-7 kg/J).
    double bsfc_kgpj = 0.0;
    /// Fuel/air mass ratio of best power (middle of the mixture efficiency plateau).
    double best_power_fuel_air_ratio = 0.080;
    /// Fuel/air mass ratio metered with the mixture lever at 1 in sea-level air.
    double full_rich_fuel_air_ratio = 0.088;
    /// Mixture lever positions below this are the idle cut-off: fuel off.
    double idle_cutoff_mixture = 0.02;
    /// Power factor as a function of fuel/air mass ratio (1 at best power, 0 at the lean and
    /// rich misfire limits). Default: the Luff correlation used by JSBSim's piston engine.
    Table1D mixture_efficiency = default_mixture_efficiency();
    /// Exhaust gas temperature (JSBSim FGPiston's figures): fuel heating value (J/kg), the
    /// share of the combustion heat that leaves with the exhaust, the stoichiometric fuel/air
    /// ratio of avgas, and the combustion efficiency as a function of equivalence ratio.
    double fuel_heating_value_jpkg = 47.3e6;
    double exhaust_heat_fraction = 0.30;
    double stoichiometric_fuel_air_ratio = 1.0 / 14.7;
    Table1D combustion_efficiency = default_combustion_efficiency();

    void validate() const;
    static Table1D default_mixture_efficiency();
    static Table1D default_combustion_efficiency();
  };

  struct Inputs {
    double engine_rpm = 0.0;
    double throttle = 0.0;  ///< 0..1 (clamped)
    double mixture = 1.0;   ///< 0..1 (clamped), 1 = full rich
    double ambient_pressure_pa = 101325.0;
    double ambient_temperature_k = 288.15;
    double ambient_density_kgpm3 = 1.225;
    bool running = true;  ///< ignition and fuel on
    bool failed = false;  ///< failure: no combustion whatever the levers
  };

  struct Outputs {
    double manifold_pressure_pa = 0.0;
    double fuel_air_ratio = 0.0;        ///< metered ratio (0 when not burning)
    double mixture_efficiency = 0.0;    ///< eta_mix at that ratio
    double combustion_torque_nm = 0.0;  ///< from IMEP, drives the shaft (>= 0)
    double loss_torque_nm = 0.0;        ///< pumping + friction, opposes rotation (>= 0)
    double brake_torque_nm = 0.0;       ///< combustion - loss (negative when windmilled)
    double brake_power_w = 0.0;         ///< brake torque * shaft speed
    double fuel_flow_kgps = 0.0;
    double air_flow_kgps = 0.0;               ///< air mass flow through the cylinders
    double exhaust_gas_temperature_k = 0.0;   ///< EGT; ambient when not burning
  };

  explicit PistonEngine(Params params);

  Outputs evaluate(const Inputs& in) const;

  const Params& params() const { return params_; }
  /// Full-throttle manifold pressure at rated rpm in sea-level air: the MAP of rated power.
  double rated_manifold_pressure_pa() const { return rated_map_pa_; }

 private:
  double manifold_pressure_pa(const Inputs& in) const;
  double friction_mep_pa(double rpm) const;
  double fuel_air_ratio(const Inputs& in) const;
  double mep_to_torque_nm(double mep_pa) const;
  double exhaust_gas_temperature_k(const Outputs& out, double ambient_k) const;

  Params params_;
  double rated_map_pa_ = 0.0;
  double rated_imep_pa_ = 0.0;
  double rated_air_flow_kgps_ = 0.0;
};

}  // namespace fedsim::flight
