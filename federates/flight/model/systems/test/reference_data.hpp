// Figures of real engines, propellers and aircraft used by the systems tests, converted to SI.
//
// Source: JSBSim (github.com/JSBSim-Team/jsbsim, commit 0b688c8), files engine/eng_io320.xml
// (Lycoming IO-320, 160 hp), engine/prop_75in2f.xml (75-inch two-blade fixed pitch),
// engine/CFM56.xml (20 000 lbf turbofan), aircraft/c172x/c172x.xml and aircraft/737/737.xml
// (mass, gear, tanks). JSBSim's structural frame is x aft, y right, z up in inches; the
// pack frame here is x forward, y right, z down in metres from the same origin.
// Other figures are named where they are used.
#pragma once

#include <Eigen/Core>
#include "common/units/units.hpp"
#include <Eigen/Geometry>
#include <numbers>
#include <vector>

#include "common/math/interpolation.hpp"
#include "flight/model/systems/landing_gear.hpp"
#include "flight/model/systems/mass_balance.hpp"
#include "flight/model/systems/piston_powerplant.hpp"
#include "flight/model/systems/turbofan.hpp"

namespace fedsim::flight::reference {

// Unit conversions (exact definitions).
constexpr double kFt = units::kFtToM;
constexpr double kIn = 0.0254;
constexpr double kLb = 0.45359237;            // kg
constexpr double kLbf = 4.4482216152605;      // N
constexpr double kHp = 745.69987158227022;    // W
constexpr double kInHg = 3386.389;            // Pa
constexpr double kSlugFt2 = 1.3558179483314;  // kg m^2
constexpr double kLbfPerFt = kLbf / kFt;      // N/m
constexpr double kDeg = units::kDegToRad;
constexpr double kG = units::kStandardGravityMps2;

// JSBSim structural inches (x aft, z up) to pack metres (x forward, z down).
inline Eigen::Vector3d from_structural_in(double x, double y, double z) {
  return {-x * kIn, y * kIn, -z * kIn};
}

// --- Lycoming IO-320 + 75-inch fixed-pitch propeller (c172x) ---------------------------

inline PistonEngine::Params io320() {
  PistonEngine::Params p;
  p.rated_power_w = 160.0 * kHp;
  p.rated_rpm = 2700.0;
  p.idle_rpm = 550.0;
  p.displacement_m3 = 320.0 * kIn * kIn * kIn;
  p.idle_manifold_pressure_pa = 10.0 * kInHg;                     // minmp
  p.intake_loss_pa_per_rpm = (101325.0 - 28.5 * kInHg) / 2700.0;  // maxmp 28.5 inHg at 2700
  // Best-power BSFC of about 0.50 lb/(hp h), typical of Lycoming four-cylinder engines
  // (JSBSim's 0.32 figure is used there with a different fuel model).
  p.bsfc_kgpj = 0.50 * kLb / (kHp * 3600.0);
  return p;
}

inline Propeller::Params prop_75in2f() {
  Propeller::Params p;
  p.diameter_m = 75.0 * kIn;
  const std::vector<double> j = {0.0, 0.1, 0.2, 0.3, 0.4, 0.5, 0.6, 0.7, 0.8, 0.9, 1.0, 1.1, 1.2,
                                 1.3, 1.4, 1.5, 1.6, 1.7, 1.8, 1.9, 2.0, 2.1, 2.2, 2.3, 5.0};
  p.thrust_coefficient = Table2D(
      j, {22.0 * kDeg}, {0.073,  0.073,  0.072,  0.071,  0.069,  0.066,  0.062,  0.055,  0.045,
                         0.034,  0.024,  0.013,  -0.006, -0.013, -0.024, -0.034, -0.045, -0.055,
                         -0.062, -0.066, -0.069, -0.071, -0.072, -0.073, -0.073});
  std::vector<double> j_cp = j;
  j_cp.insert(j_cp.end() - 1, 2.4);
  p.power_coefficient = Table2D(
      j_cp, {22.0 * kDeg}, {0.0660, 0.0700, 0.0700, 0.0660, 0.0600, 0.0530, 0.0501, 0.0469, 0.0426,
                            0.0360, 0.0282, 0.0191, 0.0155, 0.0191, 0.0282, 0.0360, 0.0426, 0.0469,
                            0.0501, 0.0516, 0.0525, 0.0525, 0.0522, 0.0511, 0.0504, 0.0493});
  p.thrust_tip_mach_factor = Table1D({0.85, 1.05}, {1.0, 0.8});
  p.power_tip_mach_factor = Table1D({0.85, 1.05, 2.00}, {1.0, 1.8, 1.4});
  return p;
}

inline PistonPowerplant::Params c172_powerplant() {
  PistonPowerplant::Params p;
  p.engine = io320();
  p.propeller = prop_75in2f();
  p.governor.constant_speed = false;
  p.governor.fine_pitch_rad = 22.0 * kDeg;
  p.thrust_line.position_m = from_structural_in(-37.7, 0.0, 26.6);
  p.shaft_inertia_kgm2 = 1.67 * kSlugFt2;  // prop ixx
  p.rotation_sense = 1;
  return p;
}

// --- CFM56 (737) --------------------------------------------------------------------------

inline Turbofan::Params cfm56() {
  Turbofan::Params p;
  p.max_thrust_n = 20000.0 * kLbf;
  std::vector<double> alt_m;
  for (double ft : {-10000.0, 0.0, 10000.0, 20000.0, 30000.0, 40000.0, 50000.0, 60000.0}) {
    alt_m.push_back(ft * kFt);
  }
  p.idle_thrust_fraction = Table2D({0.0, 0.2, 0.4, 0.6, 0.8, 1.0}, alt_m,
                                   {0.0420, 0.0436, 0.0528, 0.0694, 0.0899, 0.1183, 0.1467, 0.0,  //
                                    0.0500, 0.0501, 0.0335, 0.0544, 0.0797, 0.1049, 0.1342, 0.0,  //
                                    0.0040, 0.0047, 0.0020, 0.0272, 0.0595, 0.0891, 0.1203, 0.0,  //
                                    0.0,    0.0,    0.0,    0.0,    0.0276, 0.0718, 0.1073, 0.0,  //
                                    0.0,    0.0,    0.0,    0.0,    0.0174, 0.0468, 0.0900, 0.0,  //
                                    0.0,    0.0,    0.0,    0.0,    0.0,    0.0422, 0.0700, 0.0});
  p.max_thrust_fraction = Table2D({0.0, 0.2, 0.4, 0.6, 0.8, 1.0, 1.2}, alt_m,
                                  {1.2600, 1.0000, 0.7400, 0.5340, 0.3720, 0.2410, 0.1490, 0.0,  //
                                   1.1710, 0.9340, 0.6970, 0.5060, 0.3550, 0.2310, 0.1430, 0.0,  //
                                   1.1500, 0.9210, 0.6920, 0.5060, 0.3570, 0.2330, 0.1450, 0.0,  //
                                   1.1810, 0.9510, 0.7210, 0.5320, 0.3780, 0.2480, 0.1540, 0.0,  //
                                   1.2580, 1.0200, 0.7820, 0.5820, 0.4170, 0.2750, 0.1700, 0.0,  //
                                   1.3690, 1.1200, 0.8710, 0.6510, 0.4750, 0.3150, 0.1950, 0.0,  //
                                   0.0,    0.0,    0.0,    0.0,    0.0,    0.0,    0.0,    0.0});
  p.idle_n1_pct = 30.0;
  p.max_n1_pct = 100.0;
  p.idle_n2_pct = 60.0;
  p.max_n2_pct = 100.0;
  // Not in the JSBSim file: chosen so that flight idle to 95 % thrust takes under the 5 s of
  // 14 CFR 33.73; the core (N2) leads the fan.
  p.n1_spool_up_time_constant_s = 1.3;
  p.n1_spool_down_time_constant_s = 1.0;
  p.n2_spool_up_time_constant_s = 1.0;
  p.n2_spool_down_time_constant_s = 0.8;
  p.tsfc_kgpns = 0.657 * kLb / (kLbf * 3600.0);
  p.thrust_line.position_m = from_structural_in(540.0, -193.0, -40.0);
  return p;
}

// --- Landing gear -----------------------------------------------------------------------

inline LandingGear::Contact wheel(const char* name, Eigen::Vector3d position_m, double k_lbf_ft,
                                  double c_lbf_ft_s, double c_rebound_lbf_ft_s, double mu_roll,
                                  double max_steer_deg, LandingGear::BrakeGroup brake,
                                  bool retractable) {
  LandingGear::Contact c;
  c.name = name;
  c.position_m = position_m;
  c.spring_npm = k_lbf_ft * kLbfPerFt;
  c.damping_compression_nspm = c_lbf_ft_s * kLbfPerFt;
  c.damping_rebound_nspm = c_rebound_lbf_ft_s * kLbfPerFt;
  c.static_friction = 0.8;
  c.dynamic_friction = 0.5;
  c.rolling_friction = mu_roll;
  c.max_steer_rad = max_steer_deg * kDeg;
  c.brake_group = brake;
  c.retractable = retractable;
  return c;
}

inline LandingGear::Params c172_gear() {
  using B = LandingGear::BrakeGroup;
  LandingGear::Params p;
  p.contacts = {wheel("nose", from_structural_in(-6.8, 0.0, -20.0), 1800, 500, 2000, 0.022, 10,
                      B::kNone, false),
                wheel("left main", from_structural_in(58.2, -50.25, -18.46), 5400, 160, 320, 0.022,
                      0, B::kLeft, false),
                wheel("right main", from_structural_in(58.2, 50.25, -18.46), 5400, 160, 320, 0.022,
                      0, B::kRight, false)};
  return p;
}

inline LandingGear::Params b737_gear() {
  using B = LandingGear::BrakeGroup;
  LandingGear::Params p;
  p.contacts = {
      wheel("nose", from_structural_in(158, 0, -84), 90000, 4000, 8000, 0.02, 35, B::kNone, true),
      wheel("left main", from_structural_in(648, -100, -84), 120000, 10000, 20000, 0.02, 0,
            B::kLeft, true),
      wheel("right main", from_structural_in(648, 100, -84), 120000, 10000, 20000, 0.02, 0,
            B::kRight, true)};
  return p;
}

// --- Mass ---------------------------------------------------------------------------------

inline MassBalance::Params c172_mass() {
  MassBalance::Params p;
  p.empty_mass_kg = 1454.0 * kLb;
  p.empty_cg_m = from_structural_in(41.0, 0.0, 36.5);
  // JSBSim's inertia is of the loaded aircraft; used here as the empty aircraft's own.
  p.empty_inertia_kgm2 = Eigen::Vector3d(948.0, 1346.0, 1967.0).asDiagonal();
  p.empty_inertia_kgm2 *= kSlugFt2;
  p.point_masses = {{"pilot", 190.0 * kLb, from_structural_in(36.0, -14.0, 24.0)},
                    {"co-pilot", 140.0 * kLb, from_structural_in(36.0, 14.0, 24.0)},
                    {"passenger 1", 130.0 * kLb, from_structural_in(60.0, -14.0, 24.0)},
                    {"passenger 2", 106.0 * kLb, from_structural_in(60.0, 14.0, 24.0)},
                    {"luggage", 120.0 * kLb, from_structural_in(95.0, 0.0, 24.0)}};
  p.tanks = {{"left", 130.0 * kLb, 130.0 * kLb, from_structural_in(48.0, -112.0, 59.4)},
             {"right", 130.0 * kLb, 130.0 * kLb, from_structural_in(48.0, 112.0, 59.4)}};
  p.engine_feeds = {{0, 1}};
  return p;
}

inline MassBalance::Params b737_mass() {
  MassBalance::Params p;
  p.empty_mass_kg = 83000.0 * kLb;
  p.empty_cg_m = from_structural_in(639.0, 0.0, -40.0);
  Eigen::Matrix3d j = Eigen::Vector3d(562000.0, 1.473e6, 1.894e6).asDiagonal();
  j(0, 2) = j(2, 0) = -8000.0;  // Ixz = 8000 slug ft^2 (JSBSim negated_crossproduct_inertia)
  p.empty_inertia_kgm2 = j * kSlugFt2;
  p.tanks = {{"left wing", 10200.0 * kLb, 10000.0 * kLb, from_structural_in(520, -80, -18)},
             {"right wing", 10200.0 * kLb, 10000.0 * kLb, from_structural_in(520, 80, -18)},
             {"centre", 15000.0 * kLb, 4000.0 * kLb, from_structural_in(480, 0, -18)}};
  p.engine_feeds = {{0, 2}, {1, 2}};
  return p;
}

}  // namespace fedsim::flight::reference
