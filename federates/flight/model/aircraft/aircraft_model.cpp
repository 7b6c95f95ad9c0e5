// The aircraft executive: sub-models evaluated in one fixed order, forces and moments moved to
// the CG, the rigid body integrated.
#include "flight/model/aircraft/aircraft_model_parts.hpp"
#include "common/units/units.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <stdexcept>
#include <string>

#include "flight/model/aircraft/executive_order.hpp"
#include "flight/model/aircraft/pack_to_systems.hpp"
#include "common/atmosphere/airspeed.hpp"
#include "common/atmosphere/altimetry.hpp"

namespace fedsim::flight {

namespace {
/// The equations of motion take new mass properties when the mass has changed by this
/// fraction: a fuel-burn step changes it by ~1e-7, and each update validates the tensor (an
/// eigen-decomposition). The CG used for the moment arms is always the current one.
constexpr double kMassChangeForUpdate = 1e-6;
/// Engine settling (trim, settled resets): shaft-speed integration step and the largest
/// simulated time; a step that changes the rpm by less than the tolerance ends it.
constexpr double kSettleStepS = 0.01;
constexpr int kSettleMaxSteps = 6000;
constexpr double kSettleRelativeTolerance = 1e-10;
/// A time step long enough for the exact spool lags of a turbofan to reach their target.
constexpr double kSpoolSettleS = 1.0e4;
/// Margin on the ground-contact stability bounds (stable_ground_contact()): the per-contact
/// estimate leaves out the coupling between contacts, struts and the body's rotation. With
/// the brakes set and a 15 m/s crosswind switched on, a C172 at 50 Hz with AB2 needed 1.5
/// times the friction band of the estimate to stay free of chatter.
constexpr double kGroundContactStabilityMargin = 1.5;

EarthModelConfig earth_config(const AircraftModel::Options& options, double lat_rad,
                              double lon_rad) {
  EarthModelConfig config;
  config.kind = options.earth;
  config.flat_gravity_mps2 = options.flat_earth_gravity_mps2;
  config.origin_lat_rad = lat_rad;
  config.origin_lon_rad = lon_rad;
  return config;
}

MassProperties mass_properties_of(const MassBalance::Outputs& mass) {
  return MassProperties{mass.mass_kg, mass.inertia_kgm2};
}

bool any_retractable(const LandingGearSpec& gear) {
  return std::any_of(gear.contacts.begin(), gear.contacts.end(),
                     [](const GearContactSpec& c) { return c.retractable; });
}

void step_actuator(std::optional<Actuator>& actuator, double dt_s, double command) {
  if (actuator) actuator->step(dt_s, Actuator::Inputs{command});
}

void place_actuator(std::optional<Actuator>& actuator, double command) {
  if (actuator) actuator->reset(actuator->demand_for(command));
}

/// The largest |lambda h| on the negative real axis for which the method is stable (y' =
/// lambda y): Euler 2, RK4 2.785, AB2 1, AB3 6/11, AB4 3/10 (Hairer & Wanner, Solving ODEs
/// II, stability domains of explicit Runge-Kutta and Adams methods).
double real_axis_stability_limit(IntegrationMethod method) {
  switch (method) {
    case IntegrationMethod::kEuler:
      return 2.0;
    case IntegrationMethod::kRk4:
      return 2.785;
    case IntegrationMethod::kAb2:
      return 1.0;
    case IntegrationMethod::kAb3:
      return 6.0 / 11.0;
    case IntegrationMethod::kAb4:
      return 0.3;
  }
  return 0.3;
}

/// Angle of attack and sideslip of an air-relative body velocity (defined everywhere: both
/// are 0 at zero airspeed) and their rates from its body-frame rate of change.
void alpha_beta_rates(const Eigen::Vector3d& v, const Eigen::Vector3d& v_dot, double& alpha_dot,
                      double& beta_dot) {
  const double uw2 = v.x() * v.x() + v.z() * v.z();
  const double speed2 = uw2 + v.y() * v.y();
  constexpr double kMinSpeed2 = 1e-2;  // below 0.1 m/s the angles swing freely: rates 0
  if (uw2 < kMinSpeed2 || speed2 < kMinSpeed2) {
    alpha_dot = 0.0;
    beta_dot = 0.0;
    return;
  }
  const double uw = std::sqrt(uw2);
  alpha_dot = (v.x() * v_dot.z() - v.z() * v_dot.x()) / uw2;
  const double uw_dot = (v.x() * v_dot.x() + v.z() * v_dot.z()) / uw;
  beta_dot = (uw * v_dot.y() - v.y() * uw_dot) / speed2;
}
}  // namespace

// ---- Construction ----------------------------------------------------------------------------

void AircraftModel::Options::validate() const {
  if (substeps < 1 || substeps > 1000) {
    throw std::invalid_argument("options.substeps must be 1..1000, got " +
                                std::to_string(substeps));
  }
  if (!std::isfinite(runway_elevation_m) || std::abs(runway_elevation_m) > 10000.0) {
    throw std::invalid_argument("options.runway_elevation_m must be finite and within +-10 km");
  }
  if (!(flat_earth_gravity_mps2 > 0.0) || !std::isfinite(flat_earth_gravity_mps2)) {
    throw std::invalid_argument("options.flat_earth_gravity_mps2 must be positive");
  }
}

AircraftModel::AircraftModel(AircraftPack pack, Options options)
    : pack_(std::move(pack)),
      options_((options.validate(), options)),
      runway_elevation_m_(options_.runway_elevation_m),
      aerodynamics_(pack_),
      gear_(std::make_unique<LandingGear>(landing_gear_params(pack_.landing_gear))),
      mass_(std::make_unique<MassBalance>(mass_balance_params(pack_.mass, pack_.engines))),
      dynamics_(EarthModel(earth_config(options_, 0.0, 0.0)), mass_properties_of(mass_->outputs())),
      integrator_(options_.integrator),
      current_(std::make_unique<Evaluation>()),
      trial_(std::make_unique<Evaluation>()) {
  build_systems();
  AircraftInitialConditions parked;
  parked.position.alt_m = 1000.0;
  parked.settle_engines = false;
  reset(parked);
}

AircraftModel::~AircraftModel() = default;

void AircraftModel::build_systems() {
  if (pack_.engines.size() > kMaxEngines) {
    throw std::invalid_argument("aircraft pack '" + pack_.metadata.name + "' has " +
                                std::to_string(pack_.engines.size()) + " engines; at most " +
                                std::to_string(kMaxEngines) + " are supported");
  }
  const FlightControlsSpec& fc = pack_.flight_controls;
  surfaces_ = std::make_unique<Surfaces>();
  Surfaces& s = *surfaces_;
  if (fc.elevator) s[Surface::kElevator].emplace(actuator_params(*fc.elevator));
  if (fc.aileron) s[Surface::kAileron].emplace(actuator_params(*fc.aileron));
  if (fc.rudder) s[Surface::kRudder].emplace(actuator_params(*fc.rudder));
  if (fc.flaps) {
    s[Surface::kFlaps].emplace(kinematic_actuator_params(*fc.flaps));
    s.flap_position_at_full = s[Surface::kFlaps]->params().deflection_at_plus_one_rad;
    s.flap_full_travel_rad = fc.flaps->full_travel_rad;
  }
  if (fc.speedbrake) s[Surface::kSpeedbrake].emplace(kinematic_actuator_params(*fc.speedbrake));
  if (fc.spoilers) s[Surface::kSpoilers].emplace(kinematic_actuator_params(*fc.spoilers));
  if (fc.pitch_trim) {
    Actuator::Params trim;  // the trim's normalised travel, at the trim rate
    trim.deflection_at_plus_one_rad = 1.0;
    trim.deflection_at_minus_one_rad = -1.0;
    trim.position_min_rad = -1.0;
    trim.position_max_rad = 1.0;
    trim.rate_limit_radps = fc.pitch_trim->rate_per_s;
    s.pitch_trim.emplace(trim);
  }
  if (fc.yaw_damper) {
    YawDamper::Params damper;
    damper.gain_per_radps = fc.yaw_damper->gain_per_radps;
    damper.washout_time_constant_s = fc.yaw_damper->washout_time_constant_s;
    damper.authority = fc.yaw_damper->authority;
    s.yaw_damper.emplace(damper);
    s.yaw_damper_engaged = fc.yaw_damper->engaged_at_start;
  }
  if (fc.wing_leveller) {
    WingLeveller::Params leveller;
    leveller.bank_gain_per_rad = fc.wing_leveller->bank_gain_per_rad;
    leveller.bank_integral_gain_per_rad_s = fc.wing_leveller->bank_integral_gain_per_rad_s;
    leveller.bank_rate_gain_per_radps = fc.wing_leveller->bank_rate_gain_per_radps;
    leveller.airborne_only = fc.wing_leveller->airborne_only;
    s.wing_leveller.emplace(leveller);
    s.wing_leveller_engaged = fc.wing_leveller->engaged_at_start;
  }
  s.retractable_gear = any_retractable(pack_.landing_gear);
  if (s.retractable_gear) {
    Actuator::Params gear;
    gear.command_min = 0.0;
    gear.deflection_at_plus_one_rad = 1.0;
    gear.position_min_rad = 0.0;
    gear.position_max_rad = 1.0;
    gear.rate_limit_radps = 1.0 / pack_.landing_gear.transit_time_s;
    s[Surface::kGear].emplace(gear);
  }

  engines_.clear();
  for (const EngineSpec& spec : pack_.engines) {
    Engine engine;
    engine.type = spec.type;
    if (spec.type == EngineType::piston_propeller) {
      engine.piston.emplace(piston_powerplant_params(spec));
      engine.idle_rpm = spec.piston.idle_rpm;
    } else {
      engine.turbofan.emplace(turbofan_params(spec));
    }
    engines_.push_back(std::move(engine));
  }

  contact_kinematics_.resize(pack_.landing_gear.contacts.size());
  contact_inverse_mass_horizontal_.assign(pack_.landing_gear.contacts.size(), 0.0);
  contact_inverse_mass_vertical_.assign(pack_.landing_gear.contacts.size(), 0.0);
  contact_damping_ceiling_nspm_.assign(pack_.landing_gear.contacts.size(),
                                       std::numeric_limits<double>::infinity());
  fuel_flows_kgps_.assign(engines_.size(), 0.0);
  outputs_.engines.resize(engines_.size());
  for (std::size_t i = 0; i < engines_.size(); ++i) outputs_.engines[i].type = engines_[i].type;
  outputs_.contacts.resize(pack_.landing_gear.contacts.size());
  for (std::size_t i = 0; i < outputs_.contacts.size(); ++i) {
    outputs_.contacts[i].name = pack_.landing_gear.contacts[i].name;
  }
  outputs_.tank_fuel_kg.resize(pack_.mass.fuel_tanks.size());
  restart_turbulence();
}

// ---- Run control -----------------------------------------------------------------------------

void AircraftModel::reset(const AircraftInitialConditions& initial) {
  initial.validate();
  if (!initial.fuel_kg.empty() && initial.fuel_kg.size() != pack_.mass.fuel_tanks.size()) {
    throw std::invalid_argument("initial conditions: fuel_kg has " +
                                std::to_string(initial.fuel_kg.size()) + " tanks, the pack " +
                                std::to_string(pack_.mass.fuel_tanks.size()));
  }
  time_s_ = 0.0;
  outputs_.numerical_fault = false;
  outputs_.dropped_steps = 0;
  mass_->reset();
  for (std::size_t i = 0; i < initial.fuel_kg.size(); ++i) {
    mass_->set_tank_contents_kg(i, initial.fuel_kg[i]);
  }
  update_mass_properties(true);
  for (Engine& engine : engines_) {
    engine.running = initial.engines_running;
    if (engine.piston) engine.piston->reset(engine.running ? engine.idle_rpm : 0.0);
    if (engine.turbofan) engine.turbofan->reset(engine.running);
  }
  aerodynamics_.reset();
  if (turbulence_) turbulence_->reset();
  const FlightControlsSpec& fc = pack_.flight_controls;
  surfaces_->yaw_damper_engaged = fc.yaw_damper && fc.yaw_damper->engaged_at_start;
  surfaces_->wing_leveller_engaged = fc.wing_leveller && fc.wing_leveller->engaged_at_start;
  place_surfaces();
  set_state(initial);
  if (initial.settle_engines) settle_systems();
}

void AircraftModel::reset(const AircraftInitialConditions& initial,
                          const AircraftControls& controls) {
  set_controls(controls);
  reset(initial);
}

void AircraftModel::step(double frame_dt_s) {
  if (!(frame_dt_s > 0.0) || !std::isfinite(frame_dt_s)) return;
  const double h = frame_dt_s / static_cast<double>(options_.substeps);
  for (int i = 0; i < options_.substeps; ++i) {
    if (!current_valid_) evaluate_current();
    const RigidBodyDynamics::StateVector previous = x_;
    advance_systems(h);
    integrate_body(h);
    time_s_ += h;
    if (state_is_sound()) evaluate_current();
    if (!state_is_sound() || !evaluation_is_finite()) {
      // Never publish NaN: drop the step, keep the last sound state and say so.
      x_ = previous;
      integrator_.restart();
      alpha_dot_radps_ = 0.0;
      beta_dot_radps_ = 0.0;
      outputs_.numerical_fault = true;
      ++outputs_.dropped_steps;
      evaluate_current();
    }
  }
  fill_outputs();
}

bool AircraftModel::state_is_sound() const {
  // Finite, and an attitude quaternion near unit length (the constraint keeps it within 1e-6;
  // far off means the integration has diverged).
  return x_.allFinite() && std::abs(x_.segment<4>(6).norm() - 1.0) < 0.1;
}

bool AircraftModel::evaluation_is_finite() const {
  const Evaluation& e = *current_;
  return e.wrench.force_body_n.allFinite() && e.wrench.moment_body_nm.allFinite() &&
         std::isfinite(e.tas_mps) && std::isfinite(alpha_dot_radps_) &&
         std::isfinite(beta_dot_radps_);
}

void AircraftModel::set_controls(const AircraftControls& controls) {
  const AircraftControls c = controls.clamped();
  // Brakes and steering act on the ground reactions directly (no actuator state): the
  // evaluation at the present state must be redone before the next step uses it.
  if (c.brake_left != controls_.brake_left || c.brake_right != controls_.brake_right ||
      c.steering != controls_.steering) {
    current_valid_ = false;
  }
  controls_ = c;
}

// ---- Environment and failures ----------------------------------------------------------------

void AircraftModel::set_weather(const WeatherSettings& weather) {
  weather.validate();
  weather_ = weather;
  atmosphere_ = Atmosphere(weather_.atmosphere);
  wind_ = WindProfile(weather_.wind);
  microburst_ = WindShear(weather_.microburst);
  restart_turbulence();
  evaluate_current();
  fill_outputs();
}

void AircraftModel::restart_turbulence() {
  if (weather_.turbulence == Turbulence::Severity::kNone) {
    turbulence_.reset();
  } else {
    const std::uint64_t seed = weather_.turbulence_seed.value_or(options_.turbulence_seed);
    turbulence_ = std::make_unique<Turbulence>(
        Turbulence::Params::for_severity(weather_.turbulence, pack_.geometry.wing_span_m, seed));
  }
  gusts_active_ = false;
}

void AircraftModel::set_engine_failed(std::size_t engine, bool failed) {
  if (engine < engines_.size()) engines_[engine].failed = failed;
}

std::size_t AircraftModel::engine_count() const { return engines_.size(); }

void AircraftModel::set_engine_running(std::size_t engine, bool running) {
  if (engine < engines_.size()) engines_[engine].running = running;
}

bool AircraftModel::engine_running(std::size_t engine) const {
  return engine < engines_.size() && engines_[engine].running;
}

bool AircraftModel::engine_failed(std::size_t engine) const {
  return engine < engines_.size() && engines_[engine].failed;
}

void AircraftModel::set_runway_elevation_m(double elevation_m) {
  if (!std::isfinite(elevation_m)) return;
  runway_elevation_m_ = elevation_m;
  evaluate_current();  // the gear and the height above ground change at once
  fill_outputs();
}

void AircraftModel::set_integration_method(IntegrationMethod method) {
  integrator_.set_method(method);
  options_.integrator = method;
}

// ---- State placement -------------------------------------------------------------------------

void AircraftModel::pin_origin(const GeodeticPosition& at) {
  origin_ = {at.lat_rad, at.lon_rad, 0.0};
  origin_meridian_radius_m_ = Wgs84::meridian_radius_m(at.lat_rad);
  origin_parallel_radius_m_ = Wgs84::prime_vertical_radius_m(at.lat_rad) * std::cos(at.lat_rad);
  if (options_.earth == EarthModelKind::kFlat) {
    dynamics_ = RigidBodyDynamics(EarthModel(earth_config(options_, at.lat_rad, at.lon_rad)),
                                  dynamics_.mass_properties());
  }
}

void AircraftModel::set_state(const AircraftInitialConditions& state) {
  state.validate();
  pin_origin(state.position);
  InitialConditions body;
  body.position = state.position;
  body.velocity_ned_mps =
      state.velocity_frame == AircraftInitialConditions::VelocityFrame::kNed
          ? state.velocity_mps
          : Eigen::Vector3d(dcm_from_euler(state.attitude) * state.velocity_mps);
  body.attitude = state.attitude;
  body.omega_body_radps = state.omega_body_radps;
  body.omega_relative_to_earth = state.omega_relative_to_earth;
  x_ = RigidBodyDynamics::pack(dynamics_.initial_state(body));
  integrator_.restart();
  alpha_dot_radps_ = 0.0;
  beta_dot_radps_ = 0.0;
  gusts_active_ = false;  // no gust until the turbulence next steps (trim sees calm air)
  evaluate_current();
  fill_outputs();
}

void AircraftModel::place_surfaces() {
  Surfaces& s = *surfaces_;
  if (s.pitch_trim) s.pitch_trim->reset(s.pitch_trim->demand_for(controls_.elevator_trim));
  if (s.yaw_damper) {
    const Evaluation& e = *current_;
    s.yaw_damper->reset(yaw_rate_for_damper(e), e.mach, s.yaw_damper_engaged);
  }
  if (s.wing_leveller) {
    // At rest on the present attitude: the proportional and rate terms act at once (as
    // JSBSim's on engagement), the integral starts from zero.
    s.wing_leveller->reset();
    s.wing_leveller->step(0.0, wing_leveller_inputs(*current_));
  }
  for (Surface surface : Surfaces::kAll) {
    place_actuator(s[surface], s.command(surface, controls_));
  }
}

double AircraftModel::yaw_rate_for_damper(const Evaluation& e) const {
  // The body yaw rate relative to the air mass (JSBSim's velocities/r-aero-rad_sec).
  return e.omega_wrt_earth_body.z() - e.gust_rates_body_radps.z();
}

void AircraftModel::set_yaw_damper_engaged(bool engaged) {
  Surfaces& s = *surfaces_;
  if (!s.yaw_damper || s.yaw_damper_engaged == engaged) return;
  s.yaw_damper_engaged = engaged;
}

void AircraftModel::set_wing_leveller_engaged(bool engaged) {
  if (surfaces_->wing_leveller) surfaces_->wing_leveller_engaged = engaged;
}

bool AircraftModel::wing_leveller_engaged() const {
  return surfaces_->wing_leveller && surfaces_->wing_leveller_engaged;
}

WingLeveller::Inputs AircraftModel::wing_leveller_inputs(const Evaluation& e) const {
  const EulerAngles attitude = euler_from_dcm(e.ned_from_body);
  const Eigen::Vector3d& w = e.omega_wrt_earth_body;
  WingLeveller::Inputs in;
  in.bank_rad = attitude.phi_rad;
  in.bank_rate_radps = WingLeveller::bank_rate_radps(w.x(), w.y(), w.z(), attitude.phi_rad, attitude.theta_rad);
  in.pilot_aileron_command = controls_.aileron_command();
  in.engaged = surfaces_->wing_leveller_engaged;
  in.weight_on_wheels = gear_->outputs().weight_on_wheels;
  return in;
}

bool AircraftModel::yaw_damper_engaged() const { return surfaces_->yaw_damper && surfaces_->yaw_damper_engaged; }

void AircraftModel::settle_systems() {
  place_surfaces();
  evaluate_current();  // air data with the surfaces in place, for the engines
  for (std::size_t i = 0; i < engines_.size(); ++i) {
    Engine& engine = engines_[i];
    if (engine.turbofan) {
      const Turbofan::Inputs in = turbofan_inputs(i);
      engine.turbofan->step(kSpoolSettleS, in);  // exact lags: at the target
      engine.turbofan->step(kSpoolSettleS, in);
      continue;
    }
    const PistonPowerplant::Inputs in = piston_inputs(i);
    double previous_rpm = engine.piston->outputs().engine_rpm;
    for (int n = 0; n < kSettleMaxSteps; ++n) {
      engine.piston->step(kSettleStepS, in);
      const double rpm = engine.piston->outputs().engine_rpm;
      if (std::abs(rpm - previous_rpm) <= kSettleRelativeTolerance * std::max(rpm, 1.0)) break;
      previous_rpm = rpm;
    }
  }
  evaluate_current();
  fill_outputs();
}

// ---- Sub-model inputs ------------------------------------------------------------------------

bool AircraftModel::engine_burning(std::size_t i) const {
  const Engine& engine = engines_[i];
  const auto& starved = mass_->outputs().engine_starved;
  return engine.running && !(i < starved.size() && starved[i]);
}

PistonPowerplant::Inputs AircraftModel::piston_inputs(std::size_t i) const {
  const Evaluation& e = *current_;
  PistonPowerplant::Inputs in;
  in.throttle = controls_.throttle[i];
  in.mixture = controls_.mixture[i];
  in.propeller_lever = controls_.propeller[i];
  in.running = engine_burning(i);
  in.failed = engines_[i].failed;
  in.pressure_pa = e.air.pressure_pa;
  in.temperature_k = e.air.temperature_k;
  in.density_kgpm3 = e.air.density_kgpm3;
  in.speed_of_sound_mps = e.air.speed_of_sound_mps;
  in.air_velocity_body_mps = e.air_velocity_body_mps;
  return in;
}

Turbofan::Inputs AircraftModel::turbofan_inputs(std::size_t i) const {
  const Evaluation& e = *current_;
  Turbofan::Inputs in;
  in.throttle = controls_.throttle[i];
  in.running = engine_burning(i);
  in.failed = engines_[i].failed;
  in.mach = e.mach;
  in.density_kgpm3 = e.air.density_kgpm3;
  in.temperature_k = e.air.temperature_k;
  return in;
}

// ---- The executive order ---------------------------------------------------------------------

void AircraftModel::evaluate(const RigidBodyState& state, Evaluation& e, bool update_hysteresis) {
  evaluate_kinematics(state, e);
  for (Stage stage : kExecutiveOrder) {
    switch (stage) {
      case Stage::kAtmosphere:
        e.air = atmosphere_.at(e.geodetic.alt_m);
        break;
      case Stage::kWeather:
        evaluate_weather(e);
        break;
      case Stage::kFlightControls:
        break;  // the actuators' positions, advanced once per step, are read where they act
      case Stage::kAirData:
        evaluate_air_data(e);
        break;
      case Stage::kPropulsion:
        evaluate_propulsion(e);
        break;
      case Stage::kAerodynamics:
        evaluate_aerodynamics(state, e, update_hysteresis);
        break;
      case Stage::kGroundReactions:
        evaluate_ground_reactions(e);
        break;
      case Stage::kMassBalance:
        break;  // mass, CG and inertia as the last fuel burn left them (the CG is used above)
      case Stage::kEquationsOfMotion:
        // The wrench the equations of motion integrate.
        e.wrench.force_body_n = e.aero_force_body + e.prop_force_body + e.gear_force_body;
        e.wrench.moment_body_nm = e.aero_moment_cg + e.prop_moment_cg + e.gear_moment_cg;
        break;
    }
  }
}

void AircraftModel::evaluate_kinematics(const RigidBodyState& state, Evaluation& e) const {
  const EarthModel& earth = dynamics_.earth();

  // Kinematics of the state in local terms.
  e.ref_from_body = dcm_from_quaternion(state.attitude);
  e.geodetic = earth.geodetic(state.position_m);
  const Eigen::Matrix3d ned_from_ref = earth.ned_from_reference(e.geodetic);
  e.ned_from_body = ned_from_ref * e.ref_from_body;
  e.velocity_ned_mps = ned_from_ref * state.velocity_mps;
  e.omega_wrt_earth_body = state.omega_body_radps - e.ref_from_body.transpose() * earth.frame_rate_radps();
  e.height_agl_m = e.geodetic.alt_m - runway_elevation_m_;
  if (options_.earth == EarthModelKind::kFlat) {
    e.north_m = state.position_m.x();
    e.east_m = state.position_m.y();
  } else {
    e.north_m = (e.geodetic.lat_rad - origin_.lat_rad) * origin_meridian_radius_m_;
    e.east_m = wrap_pi(e.geodetic.lon_rad - origin_.lon_rad) * origin_parallel_radius_m_;
  }

}

void AircraftModel::evaluate_weather(Evaluation& e) const {
  // 2. Weather: steady wind, microburst, turbulence (the gusts of the present step are held).
  e.steady_wind_ned_mps = wind_.at(e.geodetic.alt_m).wind_ned_mps;
  e.wind_ned_mps = e.steady_wind_ned_mps;
  if (microburst_.params().max_outflow_mps > 0.0) {
    e.wind_ned_mps += microburst_.wind_ned_mps(e.north_m, e.east_m, e.height_agl_m);
  }
  if (turbulence_ && gusts_active_) {
    e.gust_ned_mps = turbulence_->outputs().gust_ned_mps;
    e.gust_rates_body_radps = turbulence_->outputs().gust_rates_body_radps;
  } else {
    e.gust_ned_mps.setZero();
    e.gust_rates_body_radps.setZero();
  }
  e.wind_ned_mps += e.gust_ned_mps;

}

void AircraftModel::evaluate_air_data(Evaluation& e) const {
  const Eigen::Matrix3d body_from_ned = e.ned_from_body.transpose();
  // 4. Air data.
  e.air_velocity_body_mps = body_from_ned * (e.velocity_ned_mps - e.wind_ned_mps);
  const Eigen::Vector3d& va = e.air_velocity_body_mps;
  e.tas_mps = va.norm();
  e.alpha_rad = std::atan2(va.z(), va.x());
  e.beta_rad = std::atan2(va.y(), std::hypot(va.x(), va.z()));
  e.mach = mach_number(e.tas_mps, e.air);
  e.qbar_pa = dynamic_pressure_pa(e.tas_mps, e.air);

}

void AircraftModel::evaluate_propulsion(Evaluation& e) const {
  const Eigen::Vector3d& cg = mass_->outputs().cg_m;
  // 5. Propulsion: each engine's force and moment about the datum (held over the step).
  e.prop_force_body.setZero();
  Eigen::Vector3d prop_moment_datum = Eigen::Vector3d::Zero();
  e.wrench.rotor_momentum_body_kgm2ps.setZero();
  for (const Engine& engine : engines_) {
    if (engine.piston) {
      const PistonPowerplant::Outputs& out = engine.piston->outputs();
      e.prop_force_body += out.force_body_n;
      prop_moment_datum += out.moment_datum_body_nm;
      if (options_.engine_gyroscopic_moments) {
        e.wrench.rotor_momentum_body_kgm2ps += out.rotor_angular_momentum_body_kgm2ps;
      }
    } else {
      const Turbofan::Outputs& out = engine.turbofan->outputs();
      e.prop_force_body += out.force_body_n;
      prop_moment_datum += out.moment_datum_body_nm;
    }
  }
  e.prop_moment_cg = prop_moment_datum - cg.cross(e.prop_force_body);

}

void AircraftModel::evaluate_aerodynamics(const RigidBodyState& state, Evaluation& e,
                                          bool update_hysteresis) {
  const Eigen::Vector3d& cg = mass_->outputs().cg_m;
  const Surfaces& s = *surfaces_;
  const double flap_norm = s.position(Surface::kFlaps) / s.flap_position_at_full;
  const double gear_norm = s.retractable_gear ? s.position(Surface::kGear) : 1.0;
  // 6. Aerodynamics about the aero reference point, moved to the CG. Rates relative to the air
  // mass: the earth-relative body rates minus the turbulence gust rates (Etkin).
  const Eigen::Vector3d& omega_for_aero =
      options_.aero_rates == AeroRates::kInertial ? state.omega_body_radps : e.omega_wrt_earth_body;
  const Eigen::Vector3d arp_from_cg = pack_.geometry.aero_reference_point_m - cg;
  Aerodynamics::Inputs aero_in;
  aero_in.alpha_rad = e.alpha_rad;
  aero_in.beta_rad = e.beta_rad;
  aero_in.tas_mps = e.tas_mps;
  aero_in.mach = e.mach;
  aero_in.qbar_pa = e.qbar_pa;
  aero_in.omega_air_body = omega_for_aero - e.gust_rates_body_radps;
  aero_in.alphadot_radps = alpha_dot_radps_;
  aero_in.betadot_radps = beta_dot_radps_;
  aero_in.elevator_rad = s.position(Surface::kElevator);
  aero_in.aileron_rad = s.position(Surface::kAileron);
  aero_in.rudder_rad = s.position(Surface::kRudder);
  aero_in.flap_norm = flap_norm;
  aero_in.gear_norm = gear_norm;
  aero_in.speedbrake_norm = s.position(Surface::kSpeedbrake);
  aero_in.spoiler_norm = s.position(Surface::kSpoilers);
  aero_in.aero_rp_height_agl_m = e.height_agl_m - (e.ned_from_body * arp_from_cg).z();
  e.aero = update_hysteresis
               ? aerodynamics_.evaluate(aero_in)
               : aerodynamics_.compute(aero_in, aerodynamics_.stall_hysteresis_active());
  e.aero_force_body = e.aero.force_body;
  e.aero_moment_cg = e.aero.moment_body + arp_from_cg.cross(e.aero.force_body);

}

void AircraftModel::evaluate_ground_reactions(Evaluation& e) {
  const Eigen::Vector3d& cg = mass_->outputs().cg_m;
  const Eigen::Matrix3d body_from_ned = e.ned_from_body.transpose();
  const Surfaces& s = *surfaces_;
  // 7. Ground reactions on the runway plane.
  LandingGear::contact_kinematics(gear_->params(), Eigen::Vector3d(0.0, 0.0, -e.geodetic.alt_m),
                                  e.velocity_ned_mps, body_from_ned, e.omega_wrt_earth_body, cg,
                                  contact_kinematics_);
  LandingGear::Inputs gear_in;
  gear_in.contacts = contact_kinematics_;
  gear_in.body_from_ned = body_from_ned;
  gear_in.runway_elevation_m = runway_elevation_m_;
  gear_in.steering = controls_.steering;
  gear_in.brake_left = controls_.brake_left;
  gear_in.brake_right = controls_.brake_right;
  gear_in.gear_down = !s.retractable_gear || s.position(Surface::kGear) >= 1.0;
  gear_in.min_friction_blend_speed_mps = friction_band_floor_mps_;
  gear_in.max_damping_nspm = contact_damping_ceiling_nspm_;
  gear_->step(0.0, gear_in);
  e.gear_force_body = gear_->outputs().force_body_n;
  e.gear_moment_cg = gear_->outputs().moment_datum_body_nm - cg.cross(e.gear_force_body);

}

void AircraftModel::advance_systems(double dt_s) {
  // The sub-models with a state move from the conditions of the present evaluation, in the
  // executive order (atmosphere, air data and aerodynamics have no state here: the stall
  // hysteresis follows alpha in evaluate_current(); the equations of motion are integrated
  // next, by integrate_body()).
  const Evaluation& e = *current_;
  for (Stage stage : kExecutiveOrder) {
    switch (stage) {
      case Stage::kWeather:
        if (turbulence_) {
          Turbulence::Inputs in;
          in.tas_mps = e.tas_mps;
          in.height_agl_m = e.height_agl_m;
          in.body_from_ned = e.ned_from_body.transpose();
          in.mean_wind_ned_mps = e.steady_wind_ned_mps;
          turbulence_->step(dt_s, in);
          gusts_active_ = true;
        }
        break;
      case Stage::kFlightControls: {
        // The trim and the yaw damper first: the elevator and rudder commands include them.
        Surfaces& s = *surfaces_;
        if (s.pitch_trim) s.pitch_trim->step(dt_s, Actuator::Inputs{controls_.elevator_trim});
        if (s.yaw_damper) {
          s.yaw_damper->step(dt_s, YawDamper::Inputs{yaw_rate_for_damper(e), e.mach, s.yaw_damper_engaged});
        }
        if (s.wing_leveller) s.wing_leveller->step(dt_s, wing_leveller_inputs(e));
        for (Surface surface : Surfaces::kAll) step_actuator(s[surface], dt_s, s.command(surface, controls_));
        break;
      }
      case Stage::kPropulsion:
        advance_engines(dt_s);
        break;
      case Stage::kGroundReactions:
        stable_ground_contact(dt_s);  // what this step's integration carries, held over it
        break;
      case Stage::kMassBalance:
        if (!fuel_frozen_) {  // unless frozen by the instructor: burn the fuel
          MassBalance::Inputs burn;
          burn.engine_fuel_flow_kgps = fuel_flows_kgps_;
          mass_->step(dt_s, burn);
          update_mass_properties(false);
        }
        break;
      case Stage::kAtmosphere:
      case Stage::kAirData:
      case Stage::kAerodynamics:
      case Stage::kEquationsOfMotion:
        break;
    }
  }
}

void AircraftModel::advance_engines(double dt_s) {
  for (std::size_t i = 0; i < engines_.size(); ++i) {
    Engine& engine = engines_[i];
    if (engine.piston) {
      engine.piston->step(dt_s, piston_inputs(i));
      fuel_flows_kgps_[i] = engine.piston->outputs().fuel_flow_kgps;
    } else {
      engine.turbofan->step(dt_s, turbofan_inputs(i));
      fuel_flows_kgps_[i] = engine.turbofan->outputs().fuel_flow_kgps;
    }
  }
}

void AircraftModel::integrate_body(double dt_s) {
  // 9. Equations of motion: the first derivative is the present evaluation's; the integrator's
  // trial states re-evaluate the force chain (held engines and actuators).
  const double correction = RigidBodyDynamics::quaternion_correction_per_s(
      x_, RigidBodyDynamics::stable_quaternion_constraint_kh(integrator_.method()), dt_s);
  const RigidBodyDynamics::StateVector f0 = dynamics_.derivative(x_, current_->wrench, correction);
  auto derivative = [this, correction](double, const RigidBodyDynamics::StateVector& x) {
    evaluate(RigidBodyDynamics::unpack(x), *trial_, false);
    return dynamics_.derivative(x, trial_->wrench, correction);
  };
  integrator_.step_from(time_s_, dt_s, x_, f0, derivative);
}

void AircraftModel::evaluate_current() {
  const RigidBodyState state = RigidBodyDynamics::unpack(x_);
  Evaluation& e = *current_;
  evaluate(state, e, true);
  e.accelerations = dynamics_.accelerations(state, e.wrench);
  // Body-frame rate of change of (u, v, w): the reference-frame acceleration less the
  // rotation of the body axes relative to that frame.
  const Eigen::Matrix3d body_from_ref = e.ref_from_body.transpose();
  e.velocity_body_mps = body_from_ref * state.velocity_mps;
  const Eigen::Vector3d omega_rel_body =
      state.omega_body_radps - body_from_ref * dynamics_.earth().frame_rate_radps();
  e.velocity_body_dot_mps2 = e.accelerations.acceleration_body_mps2 - omega_rel_body.cross(e.velocity_body_mps);
  // alpha-dot and beta-dot for the next evaluations (JSBSim likewise uses the last frame's):
  // the air-relative velocity changes as the ground-relative one (wind changes neglected).
  alpha_beta_rates(e.air_velocity_body_mps, e.velocity_body_dot_mps2, alpha_dot_radps_, beta_dot_radps_);
  current_valid_ = true;
}

void AircraftModel::update_mass_properties(bool force) {
  const MassBalance::Outputs& mass = mass_->outputs();
  if (force ||
      std::abs(mass.mass_kg - mass_used_by_dynamics_kg_) > kMassChangeForUpdate * mass.mass_kg) {
    dynamics_.set_mass_properties(mass_properties_of(mass));
    mass_used_by_dynamics_kg_ = mass.mass_kg;
    update_contact_inverse_masses();
  }
}

void AircraftModel::update_contact_inverse_masses() {
  // A force along e at a contact point r (from the CG, body axes) accelerates that point by
  // e (1/m + ((I^-1 (r x e)) x r) . e): the ground lies well below the CG, so a friction force
  // also rotates the aircraft and the point is lighter than the aircraft (a C172's main
  // wheel: m / m_eff = 2.5 along the body). Horizontally the larger of the along-body and
  // across-body values is kept.
  const MassBalance::Outputs& mass = mass_->outputs();
  const Eigen::Matrix3d inverse_inertia = mass.inertia_kgm2.inverse();
  auto inverse_mass = [&](const Eigen::Vector3d& arm_body, int axis) {
    const Eigen::Vector3d e = Eigen::Vector3d::Unit(axis);
    return 1.0 / mass.mass_kg + (inverse_inertia * arm_body.cross(e)).cross(arm_body).dot(e);
  };
  for (std::size_t i = 0; i < contact_inverse_mass_horizontal_.size(); ++i) {
    const Eigen::Vector3d arm_body = pack_.landing_gear.contacts[i].position_m - mass.cg_m;
    contact_inverse_mass_horizontal_[i] = std::max(inverse_mass(arm_body, 0), inverse_mass(arm_body, 1));
    contact_inverse_mass_vertical_[i] = inverse_mass(arm_body, 2);
  }
}

void AircraftModel::stable_ground_contact(double step_s) {
  // Two ground-contact terms are dampers stiff enough to overshoot an explicit step: the
  // friction band (LandingGear: mu N / band per m/s of slip) and the strut dampers (c per m/s
  // of compression rate). On a contact point of inverse mass 1/m_eff a damper of rate b is
  // an eigenvalue -b/m_eff; the method is stable while h b / m_eff stays within its real-axis
  // limit. The friction band is raised so that the contacts together stay within it
  // (h sum(mu N / m_eff) / band <= limit, mu the contact's largest, static, coefficient);
  // a strut damper above limit m_eff / h is held there (a C172's nose-strut rebound damping,
  // 29 kN s/m, is 1.1 times the AB2 limit at 50 Hz). Both only ever bind at low rates with the
  // Adams-Bashforth methods; with RK4 at 50 Hz neither does for the C172 or the 737.
  const double allowed = real_axis_stability_limit(integrator_.method()) /
                         (kGroundContactStabilityMargin * step_s);  // 1/s
  const LandingGear::Outputs& gear = gear_->outputs();
  double friction_rate_times_band = 0.0;  // sum of mu N / m_eff, m/s^2
  for (std::size_t i = 0; i < contact_damping_ceiling_nspm_.size(); ++i) {
    contact_damping_ceiling_nspm_[i] = allowed / contact_inverse_mass_vertical_[i];
    const LandingGear::ContactOutput& c = gear.contacts[i];
    if (!c.in_contact) continue;
    friction_rate_times_band += gear_->params().contacts[i].static_friction * c.normal_force_n *
                                contact_inverse_mass_horizontal_[i];
  }
  friction_band_floor_mps_ = friction_rate_times_band / allowed;
}

}  // namespace fedsim::flight
