// The facts of an aircraft pack that federates other than the flight federate need, read from the
// pack without building a flight model: its name, reference geometry (the pilot's eye point),
// mass and loading, limits and the stall-warning schedule. fedsim-visual puts its eye at the
// pilot's eye point relative to the CG at the pack's loading; fedsim-control-loading schedules
// its stick shaker from the stall-warning angles. The numbers are the flight model's own, bit
// for bit (federates/flight/model/aircraft/test/pack_facts_agreement_test.cpp).
#pragma once

#include "common/aircraft_pack/pack_sections.hpp"

#include <Eigen/Core>

#include <optional>
#include <string>

namespace fedsim::aircraft_pack {

struct PackFacts {
  PackMetadata metadata;
  ReferenceGeometry geometry;
  MassSpec mass;
  LimitsSpec limits;
  std::optional<StallWarningSpec> stall_warning;
};

/// Reads the pack's common sections (checking them as the flight model's loader does; its own
/// sections are the flight model's to check). Throws util::ConfigError ("file:line: field:
/// problem").
PackFacts load_pack_facts(const std::string& path);
/// As load_pack_facts, from YAML text; `origin` names the text in error messages.
PackFacts parse_pack_facts(const std::string& yaml_text, const std::string& origin);
/// The same from a pack's root node (the flight model's loader reads these sections with it).
PackFacts read_pack_facts(const util::ConfigNode& root);

/// The CG at the pack's loading [m, pack frame]: the empty aircraft, every point mass and every
/// tank at its initial contents, as the flight model's mass balance starts.
Eigen::Vector3d loaded_cg_m(const MassSpec& mass);

/// The pilot's eye point relative to that CG, body axes [m].
Eigen::Vector3d eye_from_cg_m(const PackFacts& facts);

/// The stall-warning schedule; throws std::invalid_argument naming the pack when it states none.
const StallWarningSpec& stall_warning_of(const PackFacts& facts);

}  // namespace fedsim::aircraft_pack
