// Turbofan engine: thrust from idle and maximum thrust tables of Mach and altitude, spool
// dynamics for N1 and N2, fuel flow from TSFC.
#pragma once

#include <Eigen/Core>

#include "common/math/interpolation.hpp"
#include "flight/model/systems/thrust_line.hpp"

namespace fedsim::flight {

/// High-bypass turbofan (seed 3.8.2, "Jet Engines"; thrust tables in the form of JSBSim's
/// turbine engine, e.g. engine/CFM56.xml).
///
/// State:   N1 and N2 (% of their maximum).
/// Inputs:  throttle (0..1), running and failure flags, Mach number, ambient density
///          (kg/m^3) and temperature (K).
/// Outputs: force_body_n along the thrust line (body axes), moment_datum_body_nm = r x F about the
///          pack datum, thrust (N), N1, N2 (%), fuel flow (kg/s), the density altitude used.
///
/// Model:
///  - The throttle schedules the spools linearly between idle and maximum:
///    N_cmd = N_idle + throttle (N_max - N_idle); 0 when shut down or failed.
///  - Each spool follows N_cmd as a first-order lag with a spool-up time constant when
///    accelerating and a spool-down one when decelerating, integrated exactly per step.
///  - Net thrust T = T_max [f_idle(M, h) + (f_max(M, h) - f_idle(M, h)) n^2], where
///    n = (N1 - N1_idle) / (N1_max - N1_idle): fan mass flow and jet velocity both rise
///    with fan speed, so thrust above idle grows with its square. f_idle and f_max are the
///    pack's IdleThrust / MilThrust tables (fraction of sea-level static maximum) of Mach and
///    ISA density altitude h (computed here from the ambient density). Below idle N1 (spooling
///    down after shutdown) T = T_max f_idle (N1 / N1_idle)^2.
///  - Fuel flow = TSFC T, TSFC = tsfc_kgpns (1 + tsfc_per_mach M) sqrt(T_amb / T_sl)
///    (the (a + b M) sqrt(theta) form of the TSFC models in Mattingly, Heiser & Pratt,
///    Aircraft Engine Design, 2nd ed., 2002), floored at min_fuel_flow_kgps while running.
///  - Exhaust gas temperature rises above ambient linearly with core speed between its rise
///    at idle and at maximum N2: EGT = T_amb + dT_idle + (dT_max - dT_idle) n2, with
///    n2 = (N2 - N2_idle) / (N2_max - N2_idle) clamped to 0..1. Defaults are CFM56 figures at
///    sea level ISA (288.15 K): about 400 C at ground idle (60 % N2; CFM56 crew training
///    figures: idle 20 % N1, 60 % N2, ~400 C EGT) and 930 C at take-off, the CFM56-3's
///    take-off EGT limit (Boeing 737-300/400/500 limitations: take-off 930 C for 5 min,
///    maximum continuous 895 C, start 725 C). The take-off figure is the limit, so the model
///    is an upper bound there: a healthy engine runs some tens of degrees below its red line.
///    Not burning (shut down or failed): ambient temperature. No thermal lag.
/// Not modelled: windmilling drag of a failed engine (belongs in the aerodynamic data),
/// reverse thrust, bleed.
class Turbofan {
 public:
  struct Params {
    double max_thrust_n = 0.0;  ///< sea-level static thrust at maximum (MilThrust = 1)
    /// Fraction of max_thrust_n at idle: rows = Mach, columns = density altitude (m).
    Table2D idle_thrust_fraction;
    /// Fraction of max_thrust_n at maximum N1: rows = Mach, columns = density altitude (m).
    Table2D max_thrust_fraction;
    double idle_n1_pct = 0.0;
    double max_n1_pct = 100.0;
    double idle_n2_pct = 0.0;
    double max_n2_pct = 100.0;
    double n1_spool_up_time_constant_s = 0.0;
    double n1_spool_down_time_constant_s = 0.0;
    double n2_spool_up_time_constant_s = 0.0;
    double n2_spool_down_time_constant_s = 0.0;
    /// Thrust specific fuel consumption, sea-level static, kg/(N s)
    /// (1 lb/(lbf h) = 2.8325e-5 kg/(N s)).
    double tsfc_kgpns = 0.0;
    double tsfc_per_mach = 0.0;       ///< relative TSFC rise per unit Mach
    double min_fuel_flow_kgps = 0.0;  ///< floor while running (idle at altitude)
    /// EGT rise above ambient at idle N2 and at maximum N2 (K); CFM56 figures (above).
    double idle_egt_rise_k = 673.15 - 288.15;
    double max_egt_rise_k = 1203.15 - 288.15;
    ThrustLine thrust_line;

    void validate() const;
  };

  struct Inputs {
    double throttle = 0.0;
    bool running = true;
    bool failed = false;
    double mach = 0.0;
    double density_kgpm3 = 1.225;
    double temperature_k = 288.15;
  };

  struct Outputs {
    Eigen::Vector3d force_body_n = Eigen::Vector3d::Zero();
    Eigen::Vector3d moment_datum_body_nm = Eigen::Vector3d::Zero();
    double thrust_n = 0.0;
    double n1_pct = 0.0;
    double n2_pct = 0.0;
    double fuel_flow_kgps = 0.0;
    double density_altitude_m = 0.0;
    double exhaust_gas_temperature_k = 0.0;  ///< EGT; ambient when not burning
  };

  explicit Turbofan(Params params);

  /// Spools at idle (running = true) or stopped; outputs for sea-level static air.
  void reset(bool running = true);
  void step(double dt_s, const Inputs& in);

  const Outputs& outputs() const { return outputs_; }
  const Params& params() const { return params_; }

  /// ISA (US Standard Atmosphere 1976) geopotential altitude whose density equals
  /// density_kgpm3; valid to 20 km, beyond which the tables are clamped anyway.
  static double density_altitude_m(double density_kgpm3);

 private:
  void fill_outputs(const Inputs& in);
  double thrust_n(const Inputs& in, double density_altitude_m) const;

  Params params_;
  Eigen::Vector3d axis_b_;
  double n1_pct_ = 0.0;
  double n2_pct_ = 0.0;
  Outputs outputs_;
};

}  // namespace fedsim::flight
