// Fills the systems models' Params (actuators, powerplants, landing gear, mass balance) from an
// aircraft pack's sections.
#pragma once

#include <vector>

#include "flight/model/aircraft/aircraft_pack.hpp"
#include "flight/model/systems/actuator.hpp"
#include "flight/model/systems/landing_gear.hpp"
#include "flight/model/systems/mass_balance.hpp"
#include "flight/model/systems/piston_powerplant.hpp"
#include "flight/model/systems/turbofan.hpp"

namespace fedsim::flight {

/// Elevator, aileron or rudder: the pack's travel, lag, rate limit (0 -> none) and clip.
Actuator::Params actuator_params(const SurfaceActuatorSpec& surface);

/// Flaps, speedbrake or spoilers as a one-sided actuator (command 0..1). The position is in
/// radians when the pack states a full travel, else normalised (1 = fully out). The pack's
/// per-segment transit times become one average rate (full travel / total time): the
/// Actuator has a single rate limit.
Actuator::Params kinematic_actuator_params(const KinematicSurfaceSpec& surface);

/// A piston_propeller engine. Rated power and rpm are the pack's maximum ones, the idle
/// manifold pressure its minimum one, and the full-throttle intake loss follows from the
/// maximum manifold pressure: (101325 Pa - max MAP) / max rpm. Engine friction, mixture and
/// governor gains keep the models' defaults. A fixed-pitch propeller (min = max pitch) gets
/// CT/CP tables with one blade-angle column and no governor.
/// Throws std::invalid_argument for a turbofan or a two-stroke engine.
PistonPowerplant::Params piston_powerplant_params(const EngineSpec& engine);

/// A turbofan engine (tables, spool time constants, TSFC, thrust line).
/// Throws std::invalid_argument for a piston engine.
Turbofan::Params turbofan_params(const EngineSpec& engine);

/// Every ground contact; cornering slip and friction blending keep the model's defaults.
LandingGear::Params landing_gear_params(const LandingGearSpec& gear);

/// Empty aircraft, point masses, tanks (as point masses: the tank-radius inertia is not
/// carried) and each engine's feed tanks.
MassBalance::Params mass_balance_params(const aircraft_pack::MassSpec& mass,
                                        const std::vector<EngineSpec>& engines);

}  // namespace fedsim::flight
