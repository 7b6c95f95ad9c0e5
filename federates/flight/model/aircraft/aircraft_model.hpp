// The aircraft executive (as JSBSim's FGFDMExec): one aircraft pack flown through atmosphere,
// weather, flight controls, air data, propulsion, aerodynamics, ground reactions, mass balance
// and the equations of motion, in that order, frame by frame.
#pragma once

#include <Eigen/Core>
#include "common/units/units.hpp"
#include <cstddef>
#include <cstdint>
#include <memory>
#include <optional>
#include <vector>

#include "flight/model/aircraft/aerodynamics.hpp"
#include "flight/model/aircraft/aircraft_controls.hpp"
#include "flight/model/aircraft/aircraft_outputs.hpp"
#include "flight/model/aircraft/aircraft_pack.hpp"
#include "flight/model/aircraft/initial_conditions.hpp"
#include "flight/model/aircraft/weather_settings.hpp"
#include "flight/model/dynamics/rigid_body_dynamics.hpp"
#include "common/atmosphere/atmosphere.hpp"
#include "common/math/integration_method.hpp"
#include "common/math/integrator.hpp"
#include "flight/model/systems/actuator.hpp"
#include "flight/model/systems/landing_gear.hpp"
#include "flight/model/systems/mass_balance.hpp"
#include "flight/model/systems/piston_powerplant.hpp"
#include "flight/model/systems/turbofan.hpp"
#include "flight/model/systems/wing_leveller.hpp"

namespace fedsim::flight {

/// The executive. Construct from a pack, reset() to initial conditions (or trim, or
/// reposition), then set_controls() and step() once per frame and read outputs().
///
/// Order of the sub-models (stated once, as data: executive_order.hpp):
///   1 atmosphere at the CG altitude, 2 weather (steady wind, microburst, turbulence),
///   3 flight controls (actuator positions), 4 air data (TAS, CAS, EAS, Mach, alpha, beta,
///   qbar), 5 propulsion, 6 aerodynamics, 7 ground reactions, 8 mass balance,
///   9 equations of motion (RigidBodyDynamics with the chosen integrator).
/// Each integration step (frame period / substeps) every sub-model with a state (actuators,
/// engines, turbulence, stall hysteresis, fuel) advances once from the conditions at the start
/// of the step, while the forces are re-evaluated at every derivative evaluation of the
/// integrator (four times per RK4 step) from the trial state: air data, aerodynamics and
/// ground reactions follow the trial state, the engines' and actuators' outputs are held.
/// Before each integration step the gear is told what the integrator carries at that step
/// (stable_ground_contact: a floor on its friction band, ceilings on its strut dampers, from
/// the contact points' effective masses and the method's stability limit).
/// Forces and moments are moved to the CG once: aerodynamics from the aero reference point,
/// engines and gear from the pack datum. Aerodynamic rates are relative to the air mass:
/// body rates minus the earth's rate minus the turbulence gust rates (Etkin).
///
/// Real-time rules: step(), set_controls(), set_engine_failed(), set_runway_elevation_m() and
/// outputs() never allocate; the constructor, reset(), the repositions, trim and set_weather()
/// may. Nothing is ever NaN: alpha and beta are 0 at zero airspeed, rates vanish below 1 mm/s,
/// and a step that would produce a non-finite state is dropped (outputs().numerical_fault).
class AircraftModel {
 public:
  static constexpr std::size_t kMaxEngines = AircraftControls::kMaxEngines;

  /// Which body rates the aerodynamic rate terms (p_hat, q_hat, r_hat) see.
  enum class AeroRates {
    kAirMass,   ///< relative to the air mass, which turns with the earth (minus gust rates)
    kInertial,  ///< relative to inertial space (NASA TM-2015-218675 check cases define their
                ///< damping so; 7.3e-5 rad/s from kAirMass on the rotating earth)
  };

  struct Options {
    /// Flat: NED at the scenario origin (the reset/reposition point at h = 0) is inertial and
    /// gravity is constant. WGS-84: rotating ellipsoid with J2 gravity (seed 3.11).
    EarthModelKind earth = EarthModelKind::kFlat;
    IntegrationMethod integrator = IntegrationMethod::kAb2;
    /// Integration steps per frame (the step is the frame period divided by this).
    int substeps = 1;
    /// Turbulence seed unless the weather names one.
    std::uint64_t turbulence_seed = 1;
    /// Add the spinning propellers' angular momentum to the moment equations (seed eqs
    /// 3.110-3.112).
    bool engine_gyroscopic_moments = true;
    AeroRates aero_rates = AeroRates::kAirMass;
    /// The terrain: a level plane at this height above MSL (m).
    double runway_elevation_m = 0.0;
    double flat_earth_gravity_mps2 = units::kStandardGravityMps2;

    /// Throws std::invalid_argument naming the bad field.
    void validate() const;
  };

  /// Builds every sub-model from the pack (throws std::invalid_argument if the pack has more
  /// than kMaxEngines engines or the options are bad). Until reset() the aircraft hangs at
  /// rest at 0 N 0 E, 1000 m, engines running at idle.
  AircraftModel(AircraftPack pack, Options options);
  ~AircraftModel();
  AircraftModel(const AircraftModel&) = delete;
  AircraftModel& operator=(const AircraftModel&) = delete;

  // ---- Run control --------------------------------------------------------------------------

  /// Starts a run: time 0, fuel and masses as the pack (or the IC) say, actuators at the
  /// commanded positions, engines running or not (and settled if asked), the flat-earth origin
  /// pinned under the IC position, the integrator history cleared.
  void reset(const AircraftInitialConditions& initial);
  /// As reset(initial) with these controls set first, so that the actuators start where they
  /// point and the engines settle at these throttles (the usual way to start a run).
  void reset(const AircraftInitialConditions& initial, const AircraftControls& controls);
  /// Advances one frame of frame_dt_s (> 0) seconds in Options::substeps integration steps.
  void step(double frame_dt_s);

  // ---- Pilot inputs -------------------------------------------------------------------------

  /// The commands for the next step (clamped, NaN-safe; see AircraftControls).
  void set_controls(const AircraftControls& controls);
  const AircraftControls& controls() const { return controls_; }

  // ---- Environment and failures -------------------------------------------------------------

  /// Replaces the weather (validates; rebuilds the wind tables and the turbulence generator,
  /// which restarts from its seed).
  void set_weather(const WeatherSettings& weather);
  const WeatherSettings& weather() const { return weather_; }
  /// Fails (true) or restores an engine (0-based): a failed engine burns no fuel and makes no
  /// power; a turbofan spools down, a piston engine windmills. Out-of-range indices are ignored.
  void set_engine_failed(std::size_t engine, bool failed);
  bool engine_failed(std::size_t engine) const;
  /// Ignition and fuel on (true) or cut off (engine 0-based; out-of-range ignored). A piston
  /// engine whose shaft still turns relights; one that has stopped needs the shaft turned
  /// (settle_systems or a reset with running engines).
  void set_engine_running(std::size_t engine, bool running);
  bool engine_running(std::size_t engine) const;
  /// Fuel freeze (an instructor function): the engines still report their fuel flow but the
  /// tanks, mass, CG and inertia stay as they are.
  void set_fuel_frozen(bool frozen) { fuel_frozen_ = frozen; }
  bool fuel_frozen() const { return fuel_frozen_; }
  /// Engages or disengages the pack's yaw damper (no effect without one). A reset engages it
  /// again if the pack says engaged_at_start.
  void set_yaw_damper_engaged(bool engaged);
  bool yaw_damper_engaged() const;
  /// Engages or disengages the pack's wing leveller (the pilot's switch; no effect without
  /// one). Disengaging resets its integral. A reset sets it to the pack's engaged_at_start.
  void set_wing_leveller_engaged(bool engaged);
  bool wing_leveller_engaged() const;
  /// Moves the terrain plane (m above MSL).
  void set_runway_elevation_m(double elevation_m);
  double runway_elevation_m() const { return runway_elevation_m_; }
  void set_integration_method(IntegrationMethod method);

  // ---- Outputs ------------------------------------------------------------------------------

  /// The state after the last step (or reset), with its forces and air data.
  const AircraftOutputs& outputs() const { return outputs_; }
  double time_s() const { return time_s_; }
  const AircraftPack& pack() const { return pack_; }
  const Options& options() const { return options_; }
  std::size_t engine_count() const;
  /// The rigid-body state (reference frame of the earth model: flat NED or ECEF).
  RigidBodyState body_state() const { return RigidBodyDynamics::unpack(x_); }
  /// The scenario origin (flat-earth NED origin; reference for north_m / east_m and the
  /// microburst).
  const GeodeticPosition& origin() const { return origin_; }
  /// The air of the present weather (ISA offsets applied).
  const Atmosphere& atmosphere() const { return atmosphere_; }

  // ---- For trim and linearisation -----------------------------------------------------------

  /// Moves the aircraft to a state without touching fuel, engines, actuators or time, re-pins
  /// the flat-earth origin there and clears the integrator history; outputs are refreshed.
  void set_state(const AircraftInitialConditions& state);
  /// Puts every actuator at the position its command asks for (and the gear at its lever) and
  /// runs the engines to their steady state at the present flight condition; outputs are
  /// refreshed. Used by trim and by a settled reset.
  void settle_systems();

 private:
  struct Engine;
  enum class Surface : std::uint8_t;
  struct Surfaces;
  struct Evaluation;

  void build_systems();
  void place_surfaces();
  double yaw_rate_for_damper(const Evaluation& e) const;
  WingLeveller::Inputs wing_leveller_inputs(const Evaluation& e) const;
  /// The force chain (executive steps 1-8) at a state; update_hysteresis for the present
  /// state only (trial states of the integrator hold the stall flag).
  void evaluate(const RigidBodyState& state, Evaluation& eval, bool update_hysteresis);
  void evaluate_kinematics(const RigidBodyState& state, Evaluation& e) const;
  void evaluate_weather(Evaluation& e) const;
  void evaluate_air_data(Evaluation& e) const;
  void evaluate_propulsion(Evaluation& e) const;
  void evaluate_aerodynamics(const RigidBodyState& state, Evaluation& e, bool update_hysteresis);
  void evaluate_ground_reactions(Evaluation& e);
  void advance_engines(double dt_s);
  void evaluate_current();
  void advance_systems(double dt_s);
  void integrate_body(double dt_s);
  void fill_outputs();
  void fill_engine_outputs();
  void fill_contact_outputs();
  void update_mass_properties(bool force);
  void update_contact_inverse_masses();
  /// Sets the friction-band floor and the strut-damping ceilings that the integrator carries
  /// at this step with the present wheel loads (a C172 with its brakes set chattered with AB2
  /// at 50 Hz: the gear's 0.25 m/s band and its nose strut's rebound damping were past the
  /// method's stability limit).
  void stable_ground_contact(double step_s);
  bool state_is_sound() const;
  bool evaluation_is_finite() const;
  void pin_origin(const GeodeticPosition& at);
  void restart_turbulence();
  bool engine_burning(std::size_t engine) const;
  PistonPowerplant::Inputs piston_inputs(std::size_t engine) const;
  Turbofan::Inputs turbofan_inputs(std::size_t engine) const;

  AircraftPack pack_;
  Options options_;
  AircraftControls controls_;
  WeatherSettings weather_;
  double runway_elevation_m_ = 0.0;
  GeodeticPosition origin_;
  double origin_meridian_radius_m_ = 0.0;
  double origin_parallel_radius_m_ = 0.0;

  // Sub-models (built from the pack at construction).
  Atmosphere atmosphere_;
  WindProfile wind_;
  WindShear microburst_;
  std::unique_ptr<Turbulence> turbulence_;
  std::unique_ptr<Surfaces> surfaces_;
  std::vector<Engine> engines_;
  Aerodynamics aerodynamics_;
  std::unique_ptr<LandingGear> gear_;
  std::unique_ptr<MassBalance> mass_;
  RigidBodyDynamics dynamics_;
  Integrator<RigidBodyDynamics::kStateSize> integrator_;

  // Scratch sized at construction so that a step never allocates.
  std::vector<LandingGear::ContactKinematics> contact_kinematics_;
  // Ground-contact conditioning for the integrator (stable_ground_contact), held over a step.
  std::vector<double> contact_inverse_mass_horizontal_;  // 1/m_eff of each contact point, 1/kg
  std::vector<double> contact_inverse_mass_vertical_;
  std::vector<double> contact_damping_ceiling_nspm_;
  double friction_band_floor_mps_ = 0.0;
  std::vector<double> fuel_flows_kgps_;
  std::unique_ptr<Evaluation> current_;  // evaluation at the present state
  std::unique_ptr<Evaluation> trial_;    // scratch for the integrator's trial states

  RigidBodyDynamics::StateVector x_;
  double time_s_ = 0.0;
  bool current_valid_ = false;
  bool gusts_active_ = false;
  bool fuel_frozen_ = false;      // false from a reset/set_state until turbulence next steps
  double alpha_dot_radps_ = 0.0;  // from the last evaluation's accelerations (one step old)
  double beta_dot_radps_ = 0.0;
  double mass_used_by_dynamics_kg_ = 0.0;
  AircraftOutputs outputs_;
};

}  // namespace fedsim::flight
