// The aircraft executive's outputs: everything a step leaves, packaged from the present
// evaluation, the rigid-body state and the sub-models (AircraftOutputs).
#include "common/atmosphere/airspeed.hpp"
#include "common/atmosphere/altimetry.hpp"
#include "common/units/units.hpp"
#include "flight/model/aircraft/aircraft_model_parts.hpp"

#include <algorithm>
#include <cmath>

namespace fedsim::flight {

// ---- Outputs ---------------------------------------------------------------------------------

void AircraftModel::fill_outputs() {
  const Evaluation& e = *current_;
  const RigidBodyState state = RigidBodyDynamics::unpack(x_);
  const MassBalance::Outputs& mass = mass_->outputs();
  AircraftOutputs& o = outputs_;
  o.time_s = time_s_;
  o.rotating_earth = options_.earth == EarthModelKind::kWgs84;

  o.geodetic = e.geodetic;
  o.height_agl_m = e.height_agl_m;
  o.position_ecef_m = dynamics_.earth().ecef(state.position_m);
  o.north_m = e.north_m;
  o.east_m = e.east_m;

  o.velocity_ned_mps = e.velocity_ned_mps;
  o.velocity_body_mps = e.velocity_body_mps;
  o.ground_speed_mps = std::hypot(e.velocity_ned_mps.x(), e.velocity_ned_mps.y());
  o.climb_rate_mps = -e.velocity_ned_mps.z();

  o.ned_from_body = e.ned_from_body;
  o.euler = euler_from_dcm(e.ned_from_body);
  Eigen::Quaterniond q(e.ned_from_body);
  if (q.w() < 0.0) q.coeffs() *= -1.0;  // scalar part >= 0: one of the two equal quaternions
  o.q_ned_from_body = to_e0123(q.normalized());

  o.omega_body_radps = state.omega_body_radps;
  o.omega_body_wrt_earth_radps = e.omega_wrt_earth_body;
  o.omega_dot_body_radps2 = e.accelerations.omega_dot_body_radps2;
  o.acceleration_body_mps2 = e.accelerations.acceleration_body_mps2;
  o.velocity_body_dot_mps2 = e.velocity_body_dot_mps2;
  o.specific_force_cg_body_mps2 = e.accelerations.specific_force_body_mps2;
  o.specific_force_eye_body_mps2 = RigidBodyDynamics::specific_force_at_body(
      e.accelerations, state.omega_body_radps, pack_.geometry.pilot_eye_point_m - mass.cg_m);
  o.load_factor_z = -o.specific_force_cg_body_mps2.z() / units::kStandardGravityMps2;

  o.tas_mps = e.tas_mps;
  o.cas_mps = cas_from_tas_mps(e.tas_mps, e.air);
  o.eas_mps = eas_from_tas_mps(e.tas_mps, e.air);
  o.mach = e.mach;
  o.alpha_rad = e.alpha_rad;
  o.beta_rad = e.beta_rad;
  o.alpha_dot_radps = alpha_dot_radps_;
  o.beta_dot_radps = beta_dot_radps_;
  o.qbar_pa = e.qbar_pa;
  o.static_pressure_pa = e.air.pressure_pa;
  o.temperature_k = e.air.temperature_k;
  o.density_kgpm3 = e.air.density_kgpm3;
  o.speed_of_sound_mps = e.air.speed_of_sound_mps;
  o.pressure_altitude_m = pressure_altitude_m(e.air.pressure_pa);
  o.wind_ned_mps = e.wind_ned_mps;
  o.gust_ned_mps = e.gust_ned_mps;
  o.gust_rates_body_radps = e.gust_rates_body_radps;
  o.air_velocity_body_mps = e.air_velocity_body_mps;

  const Surfaces& s = *surfaces_;
  o.elevator_rad = s.position(Surface::kElevator);
  o.aileron_rad = s.position(Surface::kAileron);
  o.rudder_rad = s.position(Surface::kRudder);
  o.flap_norm = s.position(Surface::kFlaps) / s.flap_position_at_full;
  o.flap_rad = o.flap_norm * s.flap_full_travel_rad;
  o.speedbrake_norm = s.position(Surface::kSpeedbrake);
  o.spoiler_norm = s.position(Surface::kSpoilers);
  o.gear_norm = s.retractable_gear ? s.position(Surface::kGear) : 1.0;
  o.pitch_trim_norm = s.trim_position(controls_);
  o.yaw_damper_engaged = s.yaw_damper && s.yaw_damper_engaged;
  o.yaw_damper_rudder = s.yaw_damper ? s.yaw_damper->outputs().rudder_command : 0.0;
  o.wing_leveller_engaged = s.wing_leveller && s.wing_leveller_engaged;
  o.wing_leveller_active = s.wing_leveller && s.wing_leveller->outputs().active;
  o.wing_leveller_aileron = s.wing_leveller ? s.wing_leveller->outputs().aileron_command : 0.0;

  o.aero = e.aero;
  o.aero_force_body_n = e.aero_force_body;
  o.aero_moment_body_nm = e.aero_moment_cg;
  o.propulsion_force_body_n = e.prop_force_body;
  o.propulsion_moment_body_nm = e.prop_moment_cg;
  o.gear_force_body_n = e.gear_force_body;
  o.gear_moment_body_nm = e.gear_moment_cg;
  o.total_force_body_n = e.wrench.force_body_n;
  o.total_moment_body_nm = e.wrench.moment_body_nm;
  o.stalled = aerodynamics_.stall_hysteresis_active();

  o.mass_kg = mass.mass_kg;
  o.fuel_kg = mass.fuel_kg;
  o.cg_m = mass.cg_m;
  o.inertia_kgm2 = mass.inertia_kgm2;
  std::copy(mass.tank_contents_kg.begin(), mass.tank_contents_kg.end(), o.tank_fuel_kg.begin());

  fill_engine_outputs();
  fill_contact_outputs();
}

void AircraftModel::fill_engine_outputs() {
  AircraftOutputs& o = outputs_;
  o.total_thrust_n = 0.0;
  const auto& starved = mass_->outputs().engine_starved;
  for (std::size_t i = 0; i < engines_.size(); ++i) {
    const Engine& engine = engines_[i];
    EngineOutputs& out = o.engines[i];
    out.failed = engine.failed;
    out.starved = i < starved.size() && starved[i];
    out.running = engine_burning(i) && !engine.failed;
    out.throttle = controls_.throttle[i];
    if (engine.piston) {
      const PistonPowerplant::Outputs& p = engine.piston->outputs();
      out.thrust_n = p.thrust_n;
      out.rpm = p.engine_rpm;
      out.propeller_rpm = p.propeller_rpm;
      out.manifold_pressure_pa = p.manifold_pressure_pa;
      out.power_w = p.brake_power_w;
      out.fuel_flow_kgps = p.fuel_flow_kgps;
      out.egt_k = p.exhaust_gas_temperature_k;
    } else {
      const Turbofan::Outputs& t = engine.turbofan->outputs();
      out.thrust_n = t.thrust_n;
      out.n1_pct = t.n1_pct;
      out.n2_pct = t.n2_pct;
      out.fuel_flow_kgps = t.fuel_flow_kgps;
      out.egt_k = t.exhaust_gas_temperature_k;
    }
    out.has_egt = true;
    o.total_thrust_n += out.thrust_n;
  }
}

void AircraftModel::fill_contact_outputs() {
  // The gear's last evaluation is the present state's: evaluate_current() always runs last.
  AircraftOutputs& o = outputs_;
  const LandingGear::Outputs& gear = gear_->outputs();
  o.weight_on_wheels = gear.weight_on_wheels;
  o.any_contact = false;
  o.gear_normal_force_n = 0.0;
  for (std::size_t i = 0; i < o.contacts.size(); ++i) {
    const LandingGear::ContactOutput& c = gear.contacts[i];
    ContactOutputs& out = o.contacts[i];
    out.weight_on_wheels = c.in_contact && c.normal_force_n > 0.0;
    out.compression_m = c.compression_m;
    out.compression_rate_mps = c.compression_rate_mps;
    out.normal_force_n = c.normal_force_n;
    out.force_body_n = c.force_body_n;
    o.any_contact = o.any_contact || out.weight_on_wheels;
    o.gear_normal_force_n += c.normal_force_n;
  }
}

}  // namespace fedsim::flight
