// Mapping of aircraft-pack sections onto the systems models' Params.
#include "flight/model/aircraft/pack_to_systems.hpp"

#include <limits>
#include <numeric>
#include <stdexcept>

namespace fedsim::flight {

namespace {
constexpr double kInfinity = std::numeric_limits<double>::infinity();
constexpr double kSeaLevelPressurePa = 101325.0;  // US 1976

ThrustLine thrust_line_of(const EngineSpec& engine) {
  ThrustLine line;
  line.position_m = engine.position_m;
  line.pitch_rad = engine.orientation_rad.y();  // roll about the thrust axis changes nothing
  line.yaw_rad = engine.orientation_rad.z();
  return line;
}

// CT or CP of blade angle: the pack's 2-D table, or its 1-D one as a single column at the
// fixed blade angle.
Table2D coefficient_table(const Table1D& fixed, const Table2D& variable, double pitch_rad) {
  if (!variable.empty()) return variable;
  return Table2D(fixed.x(), {pitch_rad}, fixed.values());
}
}  // namespace

Actuator::Params actuator_params(const SurfaceActuatorSpec& surface) {
  Actuator::Params p;
  p.command_min = -1.0;
  p.deflection_at_plus_one_rad = surface.deflection_at_plus_one_rad;
  p.deflection_at_minus_one_rad = surface.deflection_at_minus_one_rad;
  p.time_constant_s = surface.time_constant_s;
  p.rate_limit_radps = surface.rate_limit_radps > 0.0 ? surface.rate_limit_radps : kInfinity;
  p.position_min_rad = surface.min_deflection_rad;
  p.position_max_rad = surface.max_deflection_rad;
  p.validate();
  return p;
}

Actuator::Params kinematic_actuator_params(const KinematicSurfaceSpec& surface) {
  Actuator::Params p;
  p.command_min = 0.0;
  const double travel = surface.full_travel_rad > 0.0 ? surface.full_travel_rad : 1.0;
  p.deflection_at_plus_one_rad = travel;
  p.deflection_at_minus_one_rad = 0.0;
  const double total_time_s =
      std::accumulate(surface.transit_times_s.begin(), surface.transit_times_s.end(), 0.0);
  p.rate_limit_radps = total_time_s > 0.0 ? travel / total_time_s : kInfinity;
  p.position_min_rad = 0.0;
  p.position_max_rad = travel;
  p.validate();
  return p;
}

PistonPowerplant::Params piston_powerplant_params(const EngineSpec& engine) {
  if (engine.type != EngineType::piston_propeller) {
    throw std::invalid_argument("engine '" + engine.name + "' is not a piston engine");
  }
  const PistonEngineSpec& pe = engine.piston;
  const PropellerSpec& pr = engine.propeller;
  if (pe.strokes != 4) {
    throw std::invalid_argument("engine '" + engine.name + "': only four-stroke engines are modelled");
  }
  PistonPowerplant::Params p;
  p.engine.rated_power_w = pe.max_power_w;
  p.engine.rated_rpm = pe.max_rpm;
  p.engine.idle_rpm = pe.idle_rpm;
  p.engine.displacement_m3 = pe.displacement_m3;
  p.engine.idle_manifold_pressure_pa = pe.min_manifold_pressure_pa;
  p.engine.intake_loss_pa_per_rpm = (kSeaLevelPressurePa - pe.max_manifold_pressure_pa) / pe.max_rpm;
  p.engine.bsfc_kgpj = pe.bsfc_kg_per_ws;

  p.propeller.diameter_m = pr.diameter_m;
  p.propeller.thrust_coefficient =
      coefficient_table(pr.thrust_coefficient, pr.thrust_coefficient_pitch, pr.min_pitch_rad);
  p.propeller.power_coefficient =
      coefficient_table(pr.power_coefficient, pr.power_coefficient_pitch, pr.min_pitch_rad);
  p.propeller.thrust_coefficient_factor = pr.thrust_coefficient_factor;
  p.propeller.power_coefficient_factor = pr.power_coefficient_factor;
  if (pr.factor_fade) {
    p.propeller.factor_fade = Propeller::FactorFade{pr.factor_fade->start_advance_ratio,
                                                    pr.factor_fade->end_advance_ratio};
  }
  p.propeller.thrust_tip_mach_factor = pr.thrust_tip_mach_factor;
  p.propeller.power_tip_mach_factor = pr.power_tip_mach_factor;

  p.governor.constant_speed = pr.max_pitch_rad > pr.min_pitch_rad;
  p.governor.fine_pitch_rad = pr.min_pitch_rad;
  p.governor.coarse_pitch_rad = pr.max_pitch_rad;
  p.governor.feather_pitch_rad = pr.max_pitch_rad;  // packs state no feathering angle
  p.governor.governor_max_rpm = pe.max_rpm;

  p.thrust_line = thrust_line_of(engine);
  p.gear_ratio = pr.gear_ratio;
  p.shaft_inertia_kgm2 = pr.inertia_kgm2;
  p.rotation_sense = pr.spin_sense;
  p.validate();
  return p;
}

Turbofan::Params turbofan_params(const EngineSpec& engine) {
  if (engine.type != EngineType::turbofan) {
    throw std::invalid_argument("engine '" + engine.name + "' is not a turbofan");
  }
  const TurbofanSpec& t = engine.turbofan;
  Turbofan::Params p;
  p.max_thrust_n = t.max_thrust_n;
  p.idle_thrust_fraction = t.idle_thrust_fraction;
  p.max_thrust_fraction = t.max_thrust_fraction;
  p.idle_n1_pct = t.idle_n1_pct;
  p.max_n1_pct = t.max_n1_pct;
  p.idle_n2_pct = t.idle_n2_pct;
  p.max_n2_pct = t.max_n2_pct;
  p.n1_spool_up_time_constant_s = t.n1_spool_up_time_constant_s;
  p.n1_spool_down_time_constant_s = t.n1_spool_down_time_constant_s;
  p.n2_spool_up_time_constant_s = t.n2_spool_up_time_constant_s;
  p.n2_spool_down_time_constant_s = t.n2_spool_down_time_constant_s;
  p.tsfc_kgpns = t.tsfc_kg_per_ns;
  p.tsfc_per_mach = t.tsfc_per_mach;
  p.min_fuel_flow_kgps = t.min_fuel_flow_kgps;
  p.thrust_line = thrust_line_of(engine);
  p.validate();
  return p;
}

LandingGear::Params landing_gear_params(const LandingGearSpec& gear) {
  LandingGear::Params p;
  for (const GearContactSpec& c : gear.contacts) {
    LandingGear::Contact contact;
    contact.name = c.name;
    contact.type = c.type == ContactType::wheel ? LandingGear::ContactType::kWheel
                                                : LandingGear::ContactType::kStructure;
    contact.position_m = c.position_m;
    contact.spring_npm = c.spring_n_per_m;
    contact.damping_compression_nspm = c.damping_n_s_per_m;
    contact.damping_rebound_nspm = c.rebound_damping_n_s_per_m;
    contact.static_friction = c.static_friction;
    contact.dynamic_friction = c.dynamic_friction;
    contact.rolling_friction = c.rolling_friction;
    contact.max_steer_rad = c.max_steer_rad;
    contact.brake_group = c.brake_group == BrakeGroup::left    ? LandingGear::BrakeGroup::kLeft
                          : c.brake_group == BrakeGroup::right ? LandingGear::BrakeGroup::kRight
                                                               : LandingGear::BrakeGroup::kNone;
    contact.retractable = c.retractable;
    p.contacts.push_back(contact);
  }
  p.validate();
  return p;
}

MassBalance::Params mass_balance_params(const aircraft_pack::MassSpec& mass,
                                        const std::vector<EngineSpec>& engines) {
  MassBalance::Params p;
  p.empty_mass_kg = mass.empty_mass_kg;
  p.empty_cg_m = mass.empty_cg_m;
  p.empty_inertia_kgm2 = mass.empty_inertia.tensor();
  for (const aircraft_pack::PointMassSpec& m : mass.point_masses) {
    p.point_masses.push_back({m.name, m.mass_kg, m.position_m});
  }
  for (const aircraft_pack::FuelTankSpec& t : mass.fuel_tanks) {
    p.tanks.push_back({t.name, t.capacity_kg, t.initial_kg, t.position_m});
  }
  for (const EngineSpec& e : engines) {
    p.engine_feeds.emplace_back(e.fuel_tanks.begin(), e.fuel_tanks.end());
  }
  p.validate();
  return p;
}

}  // namespace fedsim::flight
