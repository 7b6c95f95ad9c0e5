// The order in which the aircraft executive runs its sub-models, stated once (as JSBSim's
// FGFDMExec states it with its model enum). Every pass over the sub-models walks this array:
// the evaluation of the force chain at a state (AircraftModel::evaluate) and the advance of the
// sub-models that carry a state (AircraftModel::advance_systems).
#pragma once

#include <array>
#include <cstdint>
#include <string_view>

namespace fedsim::flight {

enum class Stage : std::uint8_t {
  kAtmosphere,         // 1 air at the CG altitude (US 1976 with the day's offsets)
  kWeather,            // 2 steady wind, microburst, turbulence
  kFlightControls,     // 3 actuator positions
  kAirData,            // 4 TAS, alpha, beta, Mach, dynamic pressure
  kPropulsion,         // 5 engines and propellers
  kAerodynamics,       // 6 coefficient build-up, forces and moments moved to the CG
  kGroundReactions,    // 7 gear and contact points on the runway plane
  kMassBalance,        // 8 fuel burn, mass, CG, inertia
  kEquationsOfMotion,  // 9 the rigid body, integrated by the chosen method
};

inline constexpr std::array<Stage, 9> kExecutiveOrder = {
    Stage::kAtmosphere,   Stage::kWeather,      Stage::kFlightControls,
    Stage::kAirData,      Stage::kPropulsion,   Stage::kAerodynamics,
    Stage::kGroundReactions, Stage::kMassBalance, Stage::kEquationsOfMotion};

constexpr std::string_view stage_name(Stage stage) {
  switch (stage) {
    case Stage::kAtmosphere: return "atmosphere";
    case Stage::kWeather: return "weather";
    case Stage::kFlightControls: return "flight controls";
    case Stage::kAirData: return "air data";
    case Stage::kPropulsion: return "propulsion";
    case Stage::kAerodynamics: return "aerodynamics";
    case Stage::kGroundReactions: return "ground reactions";
    case Stage::kMassBalance: return "mass balance";
    case Stage::kEquationsOfMotion: return "equations of motion";
  }
  return "?";
}

}  // namespace fedsim::flight
