// Where and how an aircraft starts: position, velocity, attitude, rates and engine state, and
// the YAML initial-condition file that also sets controls, weather and the runway elevation.
#pragma once

#include <Eigen/Core>
#include <optional>
#include <string>
#include <vector>

#include "flight/model/aircraft/aircraft_controls.hpp"
#include "flight/model/aircraft/weather_settings.hpp"
#include "common/geodesy/wgs84.hpp"
#include "common/math/rotation.hpp"

namespace fedsim::flight {

/// The state an aircraft is reset or moved to. Velocities are relative to the earth; the wind
/// (WeatherSettings) is added by the model, so an aircraft started at 50 m/s north into a
/// 10 m/s north wind has 60 m/s of airspeed.
struct AircraftInitialConditions {
  enum class VelocityFrame {
    kNed,   ///< velocity_mps is (north, east, down)
    kBody,  ///< velocity_mps is (u, v, w) in body axes
  };

  /// CG position: geodetic latitude and longitude (rad), height above the WGS-84 ellipsoid
  /// (taken as mean sea level, m).
  GeodeticPosition position;
  VelocityFrame velocity_frame = VelocityFrame::kNed;
  Eigen::Vector3d velocity_mps = Eigen::Vector3d::Zero();
  /// Body attitude relative to local NED (3-2-1 Euler angles, psi true heading).
  EulerAngles attitude;
  /// Body rates p, q, r (rad/s, body axes).
  Eigen::Vector3d omega_body_radps = Eigen::Vector3d::Zero();
  /// true: omega_body_radps is relative to the earth (the model adds the earth's rate on the
  /// rotating earth); false: relative to inertial space. Identical on the flat earth.
  bool omega_relative_to_earth = true;
  /// Engines running (ignition and fuel on) or shut down.
  bool engines_running = true;
  /// Bring the engines to their steady state for the controls and airspeed at the start (a
  /// trimmed start); otherwise they start at idle (or stopped).
  bool settle_engines = true;
  /// Fuel per tank (kg, pack order); empty: the pack's initial contents.
  std::vector<double> fuel_kg;

  /// Throws std::invalid_argument naming the bad field (non-finite numbers, latitude beyond
  /// +-90 deg, negative fuel).
  void validate() const;
};

/// Everything an initial-condition file sets.
struct InitialConditionFile {
  AircraftInitialConditions initial;
  AircraftControls controls;
  WeatherSettings weather;
  std::optional<double> runway_elevation_m;
};

/// Reads an initial-condition file (format: docs/fedsim-fly.md). Strict: unknown keys, missing
/// or out-of-range numbers fail with fedsim::util::ConfigError "file:line: field: problem".
InitialConditionFile load_initial_condition_file(const std::string& path);
/// As load_initial_condition_file, from YAML text; `origin` names the text in messages.
InitialConditionFile parse_initial_condition_file(const std::string& yaml_text,
                                                  const std::string& origin);

}  // namespace fedsim::flight
