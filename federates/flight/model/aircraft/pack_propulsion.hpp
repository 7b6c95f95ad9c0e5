// Propulsion section of an aircraft pack: piston engine + propeller and turbofan figures (SI).
#pragma once

#include <Eigen/Dense>
#include <optional>
#include <string>
#include <vector>

#include "common/math/interpolation.hpp"

namespace fedsim::flight {

/// Naturally aspirated piston engine (seed 3.8.1), figures as JSBSim's piston_engine.
struct PistonEngineSpec {
  double max_power_w = 0.0;                 // rated brake power at sea level
  double displacement_m3 = 0.0;
  double idle_rpm = 0.0;
  double max_rpm = 0.0;
  double min_manifold_pressure_pa = 0.0;    // at closed throttle
  double max_manifold_pressure_pa = 0.0;    // at full throttle, sea level
  double bsfc_kg_per_ws = 0.0;              // brake-specific fuel consumption, kg/J
  int strokes = 4;                          // 4 for a four-stroke engine
  double min_throttle = 0.0;                // throttle-plate fraction at lever 0
  double max_throttle = 1.0;                // throttle-plate fraction at lever 1
  double single_magneto_power_loss = 0.0;   // fraction of power lost on one magneto
};

/// Propeller: thrust T = CT rho n^2 D^4, power P = CP rho n^3 D^5 with advance ratio
/// J = V / (n D) (n in rev/s). Tables are 1-D in J (fixed pitch) or 2-D in J (rows) and blade
/// pitch in rad (columns); exactly one of each pair is filled.
struct PropellerSpec {
  double diameter_m = 0.0;
  int blade_count = 2;
  double inertia_kgm2 = 0.0;        // about the shaft, including the rotating engine parts
  double gear_ratio = 1.0;          // engine rpm / propeller rpm
  double min_pitch_rad = 0.0;       // blade pitch at 3/4 radius
  double max_pitch_rad = 0.0;       // equal to min_pitch_rad for a fixed-pitch propeller
  int spin_sense = 1;               // +1: angular velocity along +x of the thrust axis
  double p_factor_m_per_rad = 0.0;  // lateral shift of the thrust line per rad of alpha/beta
  Table1D thrust_coefficient;       // CT(J)
  Table2D thrust_coefficient_pitch; // CT(J, pitch_rad)
  Table1D power_coefficient;        // CP(J)
  Table2D power_coefficient_pitch;  // CP(J, pitch_rad)
  // Constant multipliers on the CT and CP tables (JSBSim's <ct_factor>, <cp_factor>): a generic
  // table matched to one aircraft's published performance (data/aircraft/README.md).
  double thrust_coefficient_factor = 1.0;
  double power_coefficient_factor = 1.0;
  // Optional advance-ratio band over which those factors fade out (fedsim's, not JSBSim's): in
  // full at J <= start, linearly to 1 at J = end. None: the factors are constant.
  struct FactorFade {
    double start_advance_ratio = 0.0;
    double end_advance_ratio = 0.0;
  };
  std::optional<FactorFade> factor_fade;
  Table1D thrust_tip_mach_factor;   // CT multiplier against helical tip Mach (may be empty)
  Table1D power_tip_mach_factor;    // CP multiplier against helical tip Mach (may be empty)
};

/// Two-spool turbofan (seed 3.8.2) with JSBSim's turbine figures. Thrust tables give the
/// fraction of max_thrust_n against Mach (rows) and density altitude in m (columns).
struct TurbofanSpec {
  double max_thrust_n = 0.0;         // static sea-level maximum (military) thrust
  double bypass_ratio = 0.0;
  double tsfc_kg_per_ns = 0.0;       // thrust-specific fuel consumption, kg/(N s)
  double tsfc_per_mach = 0.0;        // relative TSFC rise per unit Mach
  double min_fuel_flow_kgps = 0.0;   // fuel flow floor while running
  double bleed_fraction = 0.0;       // fraction of core flow bled off
  double idle_n1_pct = 0.0;
  double idle_n2_pct = 0.0;
  double max_n1_pct = 100.0;
  double max_n2_pct = 100.0;
  // Spools follow their command as first-order lags with these time constants.
  double n1_spool_up_time_constant_s = 0.0;
  double n1_spool_down_time_constant_s = 0.0;
  double n2_spool_up_time_constant_s = 0.0;
  double n2_spool_down_time_constant_s = 0.0;
  Table2D idle_thrust_fraction;      // (mach, density_altitude_m)
  Table2D max_thrust_fraction;       // (mach, density_altitude_m)
};

enum class EngineType { piston_propeller, turbofan };

/// One engine and where its thrust acts. The thrust axis is body +x turned by the orientation
/// (3-2-1 yaw, pitch, roll); the position is in the pack frame.
struct EngineSpec {
  std::string name;
  EngineType type = EngineType::piston_propeller;
  Eigen::Vector3d position_m = Eigen::Vector3d::Zero();
  Eigen::Vector3d orientation_rad = Eigen::Vector3d::Zero();  // roll, pitch, yaw
  std::vector<int> fuel_tanks;  // indices into MassSpec::fuel_tanks feeding it (at least one)
  PistonEngineSpec piston;      // valid for piston_propeller
  PropellerSpec propeller;      // valid for piston_propeller
  TurbofanSpec turbofan;        // valid for turbofan
};

}  // namespace fedsim::flight
