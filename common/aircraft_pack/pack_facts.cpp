#include "common/aircraft_pack/pack_facts.hpp"

#include <stdexcept>

namespace fedsim::aircraft_pack {

PackFacts read_pack_facts(const util::ConfigNode& root) {
  check_pack_root(root);
  PackFacts facts;
  facts.metadata = read_metadata(root.child("metadata"));
  facts.metadata.file = root.file();
  facts.geometry = read_geometry(root.child("geometry"));
  facts.mass = read_mass(root.child("mass"));
  facts.limits = read_limits(root.child("limits"));
  facts.stall_warning = read_stall_warning(root);
  return facts;
}

PackFacts load_pack_facts(const std::string& path) { return read_pack_facts(util::ConfigNode::load_file(path)); }

PackFacts parse_pack_facts(const std::string& yaml_text, const std::string& origin) {
  return read_pack_facts(util::ConfigNode::parse(yaml_text, origin));
}

// The sums in the mass balance's order (federates/flight/model/systems/mass_balance.cpp), so
// that the CG is the flight model's to the last bit.
Eigen::Vector3d loaded_cg_m(const MassSpec& spec) {
  double mass = spec.empty_mass_kg;
  Eigen::Vector3d moment = spec.empty_mass_kg * spec.empty_cg_m;
  for (const PointMassSpec& m : spec.point_masses) {
    mass += m.mass_kg;
    moment += m.mass_kg * m.position_m;
  }
  for (const FuelTankSpec& t : spec.fuel_tanks) {
    mass += t.initial_kg;
    moment += t.initial_kg * t.position_m;
  }
  return moment / mass;
}

Eigen::Vector3d eye_from_cg_m(const PackFacts& facts) {
  return facts.geometry.pilot_eye_point_m - loaded_cg_m(facts.mass);
}

const StallWarningSpec& stall_warning_of(const PackFacts& facts) {
  if (!facts.stall_warning) {
    throw std::invalid_argument("aircraft pack '" + facts.metadata.name + "' (" + facts.metadata.file +
                                ") states no stall_warning schedule (data/aircraft/README.md)");
  }
  return *facts.stall_warning;
}

}  // namespace fedsim::aircraft_pack
