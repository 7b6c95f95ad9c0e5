// What the head-up display shows (seed 5.9), in SI units (docs/frames.md): the attitude and true
// heading its conformal symbols are drawn for, the velocity over the ground (the flight-path
// vector), speed, altitude, vertical speed and the flight director's cue. fedsim-visual fills it
// from the state topics (common/symbology_mapping) and draws it over its centre channel.
//
// validate() throws std::invalid_argument "<where>: field '<field>': <problem>" for a NaN, an
// infinity or a value out of its range (common/util/input_checks, common/symbology/input_checks).
#pragma once

#include "common/symbology/flight_director.hpp"

#include <Eigen/Core>

#include <string_view>

namespace fedsim::hud {

struct HudInputs {
  double pitch_rad = 0.0;               // + nose up [rad]
  double roll_rad = 0.0;                // + right wing down [rad]
  double heading_true_rad = 0.0;        // true heading: the conformal symbols need it [rad]
  double magnetic_variation_rad = 0.0;  // east +; the heading scale shows true - variation [rad]
  Eigen::Vector3d velocity_ned_mps = Eigen::Vector3d::Zero();  // over the ground: the FPV [m/s]
  double ias_mps = 0.0;
  double altitude_m = 0.0;
  double vertical_speed_mps = 0.0;
  symbology::FlightDirector flight_director;  // the guidance cue (a circle to fly the FPV onto)
};

void validate(const HudInputs& in, std::string_view where);

}  // namespace fedsim::hud
