// An aircraft data pack in memory: everything loaded and validated from a fedsim pack (YAML).
#pragma once

#include <Eigen/Dense>
#include <optional>
#include <string>
#include <vector>

#include "common/aircraft_pack/pack_sections.hpp"
#include "flight/model/aircraft/pack_aerodynamics.hpp"
#include "flight/model/aircraft/pack_flight_controls.hpp"
#include "flight/model/aircraft/pack_landing_gear.hpp"
#include "flight/model/aircraft/pack_propulsion.hpp"

namespace fedsim::flight {

// The sections every user of a pack reads (metadata, geometry, mass, limits, the stall-warning
// schedule) are common/aircraft_pack's; the flight model's own (controls, aerodynamics,
// propulsion, landing gear) are here.

struct AircraftPack {
  aircraft_pack::PackMetadata metadata;
  aircraft_pack::ReferenceGeometry geometry;
  aircraft_pack::MassSpec mass;
  FlightControlsSpec flight_controls;
  AeroModelSpec aerodynamics;
  std::vector<EngineSpec> engines;
  LandingGearSpec landing_gear;
  aircraft_pack::LimitsSpec limits;
  /// Checked against this pack's own lift when loaded (stall_warning.hpp).
  std::optional<aircraft_pack::StallWarningSpec> stall_warning;
};

/// Loads and validates a pack; throws fedsim::util::ConfigError ("file:line: field: problem")
/// for anything missing, unknown, out of range or inconsistent (a stated stall-warning schedule
/// that is not the one this pack's lift gives included).
AircraftPack load_aircraft_pack(const std::string& path);

/// As load_aircraft_pack, from YAML text; `origin` names the text in error messages.
AircraftPack parse_aircraft_pack(const std::string& yaml_text, const std::string& origin);

}  // namespace fedsim::flight
