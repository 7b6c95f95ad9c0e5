// Everything the aircraft executive reports after a step (what idl/aircraft_state.idl publishes
// and more): position, velocity, attitude, rates, air data, surfaces, engines, gear, mass.
#pragma once

#include <cstdint>

#include <Eigen/Core>
#include <string>
#include <vector>

#include "flight/model/aircraft/aerodynamics.hpp"
#include "flight/model/aircraft/pack_propulsion.hpp"
#include "common/geodesy/wgs84.hpp"
#include "common/math/rotation.hpp"

namespace fedsim::flight {

/// One engine's figures. Fields that do not apply to the engine type are 0.
struct EngineOutputs {
  EngineType type = EngineType::piston_propeller;
  bool running = false;               ///< ignition and fuel on, not failed, not starved
  bool failed = false;                ///< failed by the instructor
  bool starved = false;               ///< its feed tanks are empty
  double throttle = 0.0;              ///< command 0..1
  double thrust_n = 0.0;              ///< along the thrust line
  double rpm = 0.0;                   ///< piston: engine crankshaft speed
  double propeller_rpm = 0.0;         ///< piston: propeller speed
  double n1_pct = 0.0;                ///< turbofan: fan speed
  double n2_pct = 0.0;                ///< turbofan: core speed
  double manifold_pressure_pa = 0.0;  ///< piston
  double power_w = 0.0;               ///< piston: brake (shaft) power
  double fuel_flow_kgps = 0.0;
  /// Exhaust gas temperature: both engine types model it (has_egt true); ambient when the
  /// engine is not burning.
  bool has_egt = false;
  double egt_k = 0.0;
};

/// One ground contact (pack order).
struct ContactOutputs {
  std::string name;
  bool weight_on_wheels = false;  ///< touching the ground and carrying load
  double compression_m = 0.0;
  double compression_rate_mps = 0.0;
  double normal_force_n = 0.0;
  Eigen::Vector3d force_body_n = Eigen::Vector3d::Zero();
};

/// The state of the aircraft after a step. Frames and units as DESIGN.md; "earth-relative"
/// velocities are over the ground, "air" ones relative to the air mass.
struct AircraftOutputs {
  double time_s = 0.0;

  // Position (double precision).
  GeodeticPosition geodetic;  ///< CG: lat, lon (rad), height above the ellipsoid (m)
  double height_agl_m = 0.0;  ///< CG above the runway plane
  Eigen::Vector3d position_ecef_m = Eigen::Vector3d::Zero();
  /// CG north / east of the scenario origin (m): flat earth exact, WGS-84 along the local
  /// meridian and parallel radii at the origin.
  double north_m = 0.0, east_m = 0.0;

  // Velocity.
  Eigen::Vector3d velocity_ned_mps = Eigen::Vector3d::Zero();  ///< over the ground
  Eigen::Vector3d velocity_body_mps = Eigen::Vector3d::Zero();    ///< u, v, w over the ground
  double ground_speed_mps = 0.0;
  double climb_rate_mps = 0.0;  ///< -v_down

  // Attitude.
  /// Body attitude relative to NED, scalar first: v_ned = q v_body q* (seed eqs 3.54-3.57).
  Eigen::Vector4d q_ned_from_body = Eigen::Vector4d(1.0, 0.0, 0.0, 0.0);
  EulerAngles euler;
  Eigen::Matrix3d ned_from_body = Eigen::Matrix3d::Identity();

  // Rates and accelerations (body axes).
  Eigen::Vector3d omega_body_radps = Eigen::Vector3d::Zero();            ///< wrt inertial space
  Eigen::Vector3d omega_body_wrt_earth_radps = Eigen::Vector3d::Zero();  ///< wrt the earth
  Eigen::Vector3d omega_dot_body_radps2 = Eigen::Vector3d::Zero();
  /// Rate of change of the earth-relative velocity (reference frame), body axes: what
  /// idl/aircraft_state.idl calls acceleration_body_mps2.
  Eigen::Vector3d acceleration_body_mps2 = Eigen::Vector3d::Zero();
  /// d/dt of (u, v, w) seen in the body frame (zero in any steady flight, turns included).
  Eigen::Vector3d velocity_body_dot_mps2 = Eigen::Vector3d::Zero();
  Eigen::Vector3d specific_force_cg_body_mps2 = Eigen::Vector3d::Zero();
  Eigen::Vector3d specific_force_eye_body_mps2 = Eigen::Vector3d::Zero();  ///< pilot eye point
  double load_factor_z = 0.0;  ///< n_z = -f_z / g0 at the CG (1 in level flight)

  // Air data.
  double tas_mps = 0.0, cas_mps = 0.0, eas_mps = 0.0, mach = 0.0;
  double alpha_rad = 0.0, beta_rad = 0.0;  ///< defined (0) at zero airspeed
  double alpha_dot_radps = 0.0, beta_dot_radps = 0.0;
  double qbar_pa = 0.0;
  double static_pressure_pa = 0.0, temperature_k = 0.0, density_kgpm3 = 0.0;
  double speed_of_sound_mps = 0.0;
  double pressure_altitude_m = 0.0;
  Eigen::Vector3d wind_ned_mps = Eigen::Vector3d::Zero();      ///< total: steady + shear + gust
  Eigen::Vector3d gust_ned_mps = Eigen::Vector3d::Zero();      ///< turbulence part of the wind
  Eigen::Vector3d gust_rates_body_radps = Eigen::Vector3d::Zero();  ///< p_g, q_g, r_g (Etkin)
  Eigen::Vector3d air_velocity_body_mps = Eigen::Vector3d::Zero();

  // Surfaces as positioned by the actuators (signs: data/aircraft/README.md).
  double elevator_rad = 0.0;  ///< trailing edge down +
  double aileron_rad = 0.0;   ///< + rolls right wing down
  double rudder_rad = 0.0;    ///< trailing edge left + (yaws the nose left)
  double flap_norm = 0.0;     ///< 0..1
  double flap_rad = 0.0;      ///< flap_norm times the pack's full travel (0 if not stated)
  double speedbrake_norm = 0.0;
  double spoiler_norm = 0.0;
  double gear_norm = 0.0;  ///< 0 up, 1 down and locked
  /// Pitch trim position, -1..1 in the elevator's sense (the trim actuator's with a pack
  /// pitch_trim system, else the trim command).
  double pitch_trim_norm = 0.0;
  bool yaw_damper_engaged = false;
  double yaw_damper_rudder = 0.0;  ///< the yaw damper's rudder command (normalised, + nose right)
  bool wing_leveller_engaged = false;  ///< the pilot's switch (the pack has a wing leveller)
  bool wing_leveller_active = false;   ///< engaged and acting (airborne, if the pack says so)
  double wing_leveller_aileron = 0.0;  ///< its aileron command (normalised, + right wing down)

  // Forces and moments (body axes; moments about the CG; gravity excluded).
  Aerodynamics::Outputs aero;  ///< coefficients; its moment_body is about the aero RP
  Eigen::Vector3d aero_force_body_n = Eigen::Vector3d::Zero();
  Eigen::Vector3d aero_moment_body_nm = Eigen::Vector3d::Zero();
  Eigen::Vector3d propulsion_force_body_n = Eigen::Vector3d::Zero();
  Eigen::Vector3d propulsion_moment_body_nm = Eigen::Vector3d::Zero();
  Eigen::Vector3d gear_force_body_n = Eigen::Vector3d::Zero();
  Eigen::Vector3d gear_moment_body_nm = Eigen::Vector3d::Zero();
  Eigen::Vector3d total_force_body_n = Eigen::Vector3d::Zero();
  Eigen::Vector3d total_moment_body_nm = Eigen::Vector3d::Zero();
  bool stalled = false;  ///< stall hysteresis flag

  // Mass.
  double mass_kg = 0.0;
  double fuel_kg = 0.0;
  Eigen::Vector3d cg_m = Eigen::Vector3d::Zero();  ///< pack frame
  Eigen::Matrix3d inertia_kgm2 = Eigen::Matrix3d::Identity();
  std::vector<double> tank_fuel_kg;  ///< sized at construction

  // Propulsion.
  double total_thrust_n = 0.0;
  std::vector<EngineOutputs> engines;  ///< sized at construction

  // Ground contact.
  bool weight_on_wheels = false;         ///< any wheel carries load
  bool any_contact = false;              ///< any contact (wheel or structure) carries load
  double gear_normal_force_n = 0.0;      ///< sum over contacts
  std::vector<ContactOutputs> contacts;  ///< sized at construction

  /// Set when a step produced a non-finite state: the model kept the last finite state (the
  /// step is lost) instead of publishing NaN. Cleared by reset.
  bool numerical_fault = false;
  /// Integration steps dropped that way since the last reset (hosts count and report them).
  std::uint64_t dropped_steps = 0;

  /// The earth the state refers to: true on the rotating WGS-84 earth (omega_body_radps is
  /// relative to inertial space, earth rate included); false on the flat earth, whose NED frame
  /// at the origin is taken as inertial. An INS or a motion cue needs to know which.
  bool rotating_earth = false;
};

}  // namespace fedsim::flight
