// The aircraft executive's sub-model holders and its evaluation record: private to
// aircraft_model.cpp (the executive) and aircraft_model_outputs.cpp (output packaging).
#pragma once

#include "flight/model/aircraft/aircraft_model.hpp"

#include <algorithm>
#include <array>
#include <cstdint>
#include <optional>

#include "flight/model/systems/wing_leveller.hpp"
#include "flight/model/systems/yaw_damper.hpp"

namespace fedsim::flight {

// ---- Sub-model holders -----------------------------------------------------------------------

struct AircraftModel::Engine {
  EngineType type = EngineType::piston_propeller;
  std::optional<PistonPowerplant> piston;
  std::optional<Turbofan> turbofan;
  double idle_rpm = 0.0;
  bool running = true;  // ignition and fuel selected on
  bool failed = false;  // instructor failure
};

/// The actuated surfaces (and the gear), each driven by one command of AircraftControls.
enum class AircraftModel::Surface : std::uint8_t {
  kElevator, kAileron, kRudder, kFlaps, kSpeedbrake, kSpoilers, kGear };

struct AircraftModel::Surfaces {
  static constexpr std::array<Surface, 7> kAll = {Surface::kElevator, Surface::kAileron,
                                                  Surface::kRudder,   Surface::kFlaps,
                                                  Surface::kSpeedbrake, Surface::kSpoilers,
                                                  Surface::kGear};
  /// The command an actuator follows (the gear: 0 up .. 1 down, at the pack's transit rate).
  /// The elevator takes the pilot's elevator plus the pitch trim's present position (with a
  /// pitch-trim system; else the trim command itself), the rudder the pilot's rudder, its trim
  /// and the yaw damper's command, the aileron the pilot's aileron, its trim and the wing
  /// leveller's command, each sum clipped to -1..1 (JSBSim's "Pitch Trim Sum", "Rudder Sum"
  /// and "fcs/roll-trim-sum").
  double command(Surface surface, const AircraftControls& c) const {
    switch (surface) {
      case Surface::kElevator: return std::clamp(c.elevator + trim_position(c), -1.0, 1.0);
      case Surface::kAileron:
        return std::clamp(c.aileron_command() + (wing_leveller ? wing_leveller->outputs().aileron_command : 0.0),
                          -1.0, 1.0);
      case Surface::kRudder:
        return std::clamp(c.rudder + c.rudder_trim + (yaw_damper ? yaw_damper->outputs().rudder_command : 0.0),
                          -1.0, 1.0);
      case Surface::kFlaps: return c.flaps;
      case Surface::kSpeedbrake: return c.speedbrake;
      case Surface::kSpoilers: return c.spoilers;
      case Surface::kGear: return c.gear_down ? 1.0 : 0.0;
    }
    return 0.0;
  }
  std::optional<Actuator>& operator[](Surface surface) {
    return actuators[static_cast<std::size_t>(surface)];
  }
  /// An actuator's position (0 for a surface the pack does not have).
  double position(Surface surface) const {
    const auto& a = actuators[static_cast<std::size_t>(surface)];
    return a ? a->outputs().position_rad : 0.0;
  }
  /// The pitch trim's position (normalised -1..1): the trim actuator's, or the command itself
  /// when the pack has no trim system.
  double trim_position(const AircraftControls& c) const {
    return pitch_trim ? pitch_trim->outputs().position_rad : c.elevator_trim;
  }
  std::array<std::optional<Actuator>, kAll.size()> actuators;
  std::optional<Actuator> pitch_trim;  // normalised position, moving at the trim rate
  std::optional<YawDamper> yaw_damper;
  bool yaw_damper_engaged = false;
  std::optional<WingLeveller> wing_leveller;
  bool wing_leveller_engaged = false;
  bool retractable_gear = false;
  double flap_position_at_full = 1.0;  // actuator position at flap command 1 (rad or 1)
  double flap_full_travel_rad = 0.0;
};

/// Everything one evaluation of the force chain works out, in executive order.
struct AircraftModel::Evaluation {
  // Kinematics of the state.
  GeodeticPosition geodetic;
  Eigen::Matrix3d ref_from_body = Eigen::Matrix3d::Identity();
  Eigen::Matrix3d ned_from_body = Eigen::Matrix3d::Identity();
  Eigen::Vector3d velocity_ned_mps = Eigen::Vector3d::Zero();
  Eigen::Vector3d omega_wrt_earth_body = Eigen::Vector3d::Zero();
  double height_agl_m = 0.0;
  double north_m = 0.0, east_m = 0.0;
  // 1 atmosphere.
  AirProperties air;
  // 2 weather.
  Eigen::Vector3d steady_wind_ned_mps = Eigen::Vector3d::Zero();
  Eigen::Vector3d gust_ned_mps = Eigen::Vector3d::Zero();
  Eigen::Vector3d gust_rates_body_radps = Eigen::Vector3d::Zero();
  Eigen::Vector3d wind_ned_mps = Eigen::Vector3d::Zero();
  // 4 air data.
  Eigen::Vector3d air_velocity_body_mps = Eigen::Vector3d::Zero();
  double tas_mps = 0.0, alpha_rad = 0.0, beta_rad = 0.0, mach = 0.0, qbar_pa = 0.0;
  // 5-7 forces (body axes) and moments about the CG.
  Aerodynamics::Outputs aero;
  Eigen::Vector3d aero_force_body = Eigen::Vector3d::Zero(), aero_moment_cg = Eigen::Vector3d::Zero();
  Eigen::Vector3d prop_force_body = Eigen::Vector3d::Zero(), prop_moment_cg = Eigen::Vector3d::Zero();
  Eigen::Vector3d gear_force_body = Eigen::Vector3d::Zero(), gear_moment_cg = Eigen::Vector3d::Zero();
  Wrench wrench;
  // Accelerations (current evaluation only).
  RigidBodyAccelerations accelerations;
  Eigen::Vector3d velocity_body_mps = Eigen::Vector3d::Zero();
  Eigen::Vector3d velocity_body_dot_mps2 = Eigen::Vector3d::Zero();
};

}  // namespace fedsim::flight
