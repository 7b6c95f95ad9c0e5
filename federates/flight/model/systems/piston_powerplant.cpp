// Piston engine driving a propeller: shaft-speed dynamics, blade-angle control and the
// resulting force and moment on the airframe.
#include "flight/model/systems/piston_powerplant.hpp"
#include "common/units/units.hpp"

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>
#include <string>

#include "flight/model/systems/param_checks.hpp"

namespace fedsim::flight {

namespace {

// Runs a sub-model's validate() and prefixes its message with the sub-model's field name.
template <typename SubParams>
void validate_part(const SubParams& part, const std::string& prefix) {
  try {
    part.validate();
  } catch (const std::invalid_argument& e) {
    throw std::invalid_argument(prefix + e.what());
  }
}
}  // namespace

void PistonPowerplant::Params::validate() const {
  validate_part(engine, "engine.");
  validate_part(propeller, "propeller.");
  validate_part(governor, "governor.");
  thrust_line.validate("thrust_line.");
  param_checks::positive(gear_ratio, "gear_ratio");
  param_checks::positive(shaft_inertia_kgm2, "shaft_inertia_kgm2");
  if (rotation_sense != 1 && rotation_sense != -1) {
    param_checks::fail("rotation_sense", "must be +1 or -1", rotation_sense);
  }
}

PistonPowerplant::PistonPowerplant(Params params)
    : params_((params.validate(), std::move(params))),
      engine_(params_.engine),
      propeller_(params_.propeller),
      governor_(params_.governor),
      axis_b_(params_.thrust_line.axis_body()) {
  reset();
}

void PistonPowerplant::reset(double engine_rpm) {
  omega_radps_ = std::max(engine_rpm, 0.0) / params_.gear_ratio * units::kRpmToRadps;
  governor_.reset();
  const Inputs still_air;
  fill_outputs(still_air, evaluate(still_air));
}

double PistonPowerplant::propeller_rpm() const { return omega_radps_ / units::kRpmToRadps; }

PistonPowerplant::Snapshot PistonPowerplant::evaluate(const Inputs& in) const {
  Snapshot s;
  PistonEngine::Inputs engine_in;
  engine_in.engine_rpm = propeller_rpm() * params_.gear_ratio;
  engine_in.throttle = in.throttle;
  engine_in.mixture = in.mixture;
  engine_in.ambient_pressure_pa = in.pressure_pa;
  engine_in.ambient_temperature_k = in.temperature_k;
  engine_in.ambient_density_kgpm3 = in.density_kgpm3;
  engine_in.running = in.running;
  engine_in.failed = in.failed;
  s.engine = engine_.evaluate(engine_in);

  Propeller::Inputs prop_in;
  prop_in.rpm = propeller_rpm();
  prop_in.axial_airspeed_mps = in.air_velocity_body_mps.dot(axis_b_);
  prop_in.density_kgpm3 = in.density_kgpm3;
  prop_in.speed_of_sound_mps = in.speed_of_sound_mps;
  prop_in.blade_angle_rad = governor_.outputs().blade_angle_rad;
  s.propeller = propeller_.evaluate(prop_in);
  return s;
}

void PistonPowerplant::integrate_shaft(double dt_s, const Snapshot& now) {
  const double g = params_.gear_ratio;
  const double inertia = params_.shaft_inertia_kgm2;
  const double drive_nm = g * now.engine.combustion_torque_nm - now.propeller.torque_nm;
  double omega = omega_radps_ + dt_s * drive_nm / inertia;
  // Losses brake toward zero and stop there (Coulomb-like), never spin the shaft backward.
  const double loss_radps = dt_s * g * now.engine.loss_torque_nm / inertia;
  omega = omega > loss_radps ? omega - loss_radps : 0.0;
  omega_radps_ = std::isfinite(omega) ? omega : 0.0;
}

void PistonPowerplant::step(double dt_s, const Inputs& in) {
  if (!(dt_s > 0.0)) return;
  const Snapshot now = evaluate(in);
  PropellerGovernor::Inputs gov_in;
  gov_in.lever = in.propeller_lever;
  gov_in.feather = in.feather;
  gov_in.engine_rpm = propeller_rpm() * params_.gear_ratio;
  integrate_shaft(dt_s, now);
  governor_.step(dt_s, gov_in);
  fill_outputs(in, evaluate(in));
}

void PistonPowerplant::fill_outputs(const Inputs& in, const Snapshot& now) {
  Outputs& out = outputs_;
  const double sense = params_.rotation_sense;
  out.thrust_n = now.propeller.thrust_n;
  out.force_body_n = out.thrust_n * axis_b_;
  out.moment_datum_body_nm = params_.thrust_line.position_m.cross(out.force_body_n) -
                          sense * now.propeller.torque_nm * axis_b_;
  out.rotor_angular_momentum_body_kgm2ps = sense * params_.shaft_inertia_kgm2 * omega_radps_ * axis_b_;
  out.propeller_rpm = propeller_rpm();
  out.engine_rpm = out.propeller_rpm * params_.gear_ratio;
  out.blade_angle_rad = governor_.outputs().blade_angle_rad;
  out.selected_rpm = governor_.selected_rpm(in.propeller_lever);
  out.advance_ratio = now.propeller.advance_ratio;
  out.propeller_torque_nm = now.propeller.torque_nm;
  out.propeller_efficiency = now.propeller.efficiency;
  out.manifold_pressure_pa = now.engine.manifold_pressure_pa;
  out.brake_power_w = now.engine.brake_power_w;
  out.fuel_flow_kgps = now.engine.fuel_flow_kgps;
  out.exhaust_gas_temperature_k = now.engine.exhaust_gas_temperature_k;
}

}  // namespace fedsim::flight
