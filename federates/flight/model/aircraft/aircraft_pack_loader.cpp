// Aircraft-pack loader (data/aircraft/README.md): the top level and the sections every user of
// a pack reads (metadata, geometry, mass, limits, the stall-warning schedule) through
// common/aircraft_pack, the flight model's own sections here; then the systems models' and the
// lift's checks.
#include "common/aircraft_pack/pack_facts.hpp"
#include "flight/model/aircraft/aircraft_pack.hpp"
#include "flight/model/aircraft/pack_reading.hpp"
#include "flight/model/aircraft/pack_to_systems.hpp"
#include "flight/model/aircraft/stall_warning.hpp"

#include <sstream>
#include <stdexcept>
#include <utility>

namespace fedsim::flight {

namespace {

using namespace pack_detail;

// The systems models validate their own Params; a pack they reject is refused at load time,
// pointing at the section that fills them.
template <typename Build>
void accepted_by_model(const ConfigNode& section, Build build) {
  try {
    build();
  } catch (const std::invalid_argument& e) {
    section.fail(std::string("rejected by the systems model: ") + e.what());
  }
}

void check_against_systems_models(const AircraftPack& pack, const ConfigNode& root) {
  const ConfigNode controls = root.child("flight_controls");
  const FlightControlsSpec& fc = pack.flight_controls;
  const std::pair<const char*, const std::optional<SurfaceActuatorSpec>*> surfaces[] = {
      {"elevator", &fc.elevator}, {"aileron", &fc.aileron}, {"rudder", &fc.rudder}};
  for (const auto& [key, surface] : surfaces) {
    if (*surface) accepted_by_model(controls.child(key), [&] { actuator_params(**surface); });
  }
  const std::pair<const char*, const std::optional<KinematicSurfaceSpec>*> kinematics[] = {
      {"flaps", &fc.flaps}, {"speedbrake", &fc.speedbrake}, {"spoilers", &fc.spoilers}};
  for (const auto& [key, surface] : kinematics) {
    if (*surface) {
      accepted_by_model(controls.child(key), [&] { kinematic_actuator_params(**surface); });
    }
  }
  const auto engine_nodes = root.child("propulsion").child("engines").items();
  for (std::size_t i = 0; i < pack.engines.size(); ++i) {
    const EngineSpec& engine = pack.engines[i];
    accepted_by_model(engine_nodes[i], [&] {
      if (engine.type == EngineType::turbofan) {
        turbofan_params(engine);
      } else {
        piston_powerplant_params(engine);
      }
    });
  }
  accepted_by_model(root.child("landing_gear"),
                    [&] { landing_gear_params(pack.landing_gear); });
  accepted_by_model(root.child("mass"), [&] { mass_balance_params(pack.mass, pack.engines); });
}

// A stated stall-warning schedule is the one this pack's own lift gives (stall_warning.hpp), to
// the last bit: the control loader reads the schedule without the flight model.
void check_stall_warning(const AircraftPack& pack, const ConfigNode& root) {
  if (!pack.stall_warning) return;
  const ConfigNode node = root.child("stall_warning");
  const aircraft_pack::StallWarningSpec& stated = *pack.stall_warning;
  for (std::size_t i = 0; i < stated.flap_norm.size(); ++i) {
    StallAngles computed;
    try {
      computed = stall_angles(pack, stated.flap_norm[i]);
    } catch (const std::invalid_argument& e) {
      node.fail(e.what());
    }
    if (computed.alpha_warning_rad != stated.alpha_rad[i]) {
      std::ostringstream why;
      why.precision(17);
      why << "alpha_rad[" << i << "] is " << stated.alpha_rad[i] << " rad, but this pack's lift gives "
          << computed.alpha_warning_rad << " rad at flaps " << stated.flap_norm[i]
          << " (CL_max / 1.05^2): state that";
      node.fail(why.str());
    }
  }
}

AircraftPack read_pack(const ConfigNode& root) {
  aircraft_pack::PackFacts common = aircraft_pack::read_pack_facts(root);  // the top level too
  AircraftPack pack;
  pack.metadata = std::move(common.metadata);
  pack.geometry = common.geometry;
  pack.mass = std::move(common.mass);
  pack.limits = common.limits;
  pack.stall_warning = std::move(common.stall_warning);
  pack.flight_controls = read_flight_controls(root.child("flight_controls"));
  pack.aerodynamics = read_aerodynamics(root.child("aerodynamics"), pack.flight_controls);
  pack.engines = read_propulsion(root.child("propulsion"), pack.mass);
  pack.landing_gear = read_landing_gear(root.child("landing_gear"));
  check_against_systems_models(pack, root);
  check_stall_warning(pack, root);
  return pack;
}

}  // namespace

AircraftPack load_aircraft_pack(const std::string& path) {
  return read_pack(util::ConfigNode::load_file(path));
}

AircraftPack parse_aircraft_pack(const std::string& yaml_text, const std::string& origin) {
  return read_pack(util::ConfigNode::parse(yaml_text, origin));
}

}  // namespace fedsim::flight
