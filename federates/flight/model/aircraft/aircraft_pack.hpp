// An aircraft data pack in memory: everything loaded and validated from a fedsim pack (YAML).
#pragma once

#include <Eigen/Dense>
#include <optional>
#include <string>
#include <vector>

#include "flight/model/aircraft/pack_aerodynamics.hpp"
#include "flight/model/aircraft/pack_flight_controls.hpp"
#include "flight/model/aircraft/pack_landing_gear.hpp"
#include "flight/model/aircraft/pack_propulsion.hpp"

namespace fedsim::flight {

// All positions below are in the pack frame: body axes (x forward, y right, z down), metres,
// from the pack's datum point. All angles are radians, whatever unit the YAML key states.

struct PackMetadata {
  std::string name;
  std::string source;                // where the figures come from (files, commit, report)
  std::string description;           // optional
  std::vector<std::string> notes;    // optional, e.g. what a converter left out
  std::string file;                  // path the pack was loaded from
};

struct ReferenceGeometry {
  double wing_area_m2 = 0.0;   // S
  double wing_span_m = 0.0;    // b, scales roll and yaw moments and p_hat, r_hat
  double mean_chord_m = 0.0;   // c, scales pitch moment and q_hat, alphadot_hat
  Eigen::Vector3d aero_reference_point_m = Eigen::Vector3d::Zero();
  Eigen::Vector3d pilot_eye_point_m = Eigen::Vector3d::Zero();
  Eigen::Vector3d visual_reference_point_m = Eigen::Vector3d::Zero();  // reported position
};

/// Moments and products of inertia; products are integrals (Ixz = integral of x z dm), so the
/// tensor has them negated off the diagonal.
struct InertiaSpec {
  double ixx_kgm2 = 0.0, iyy_kgm2 = 0.0, izz_kgm2 = 0.0;
  double ixy_kgm2 = 0.0, ixz_kgm2 = 0.0, iyz_kgm2 = 0.0;

  Eigen::Matrix3d tensor() const {
    Eigen::Matrix3d j;
    j << ixx_kgm2, -ixy_kgm2, -ixz_kgm2,  //
        -ixy_kgm2, iyy_kgm2, -iyz_kgm2,   //
        -ixz_kgm2, -iyz_kgm2, izz_kgm2;
    return j;
  }
};

struct PointMassSpec {
  std::string name;
  double mass_kg = 0.0;
  Eigen::Vector3d position_m = Eigen::Vector3d::Zero();
};

/// A fuel tank is a point mass at its position; a tank with a radius also has the inertia of
/// a solid sphere of its contents about its own centre, 0.4 m r^2 on each axis (as JSBSim).
struct FuelTankSpec {
  std::string name;
  Eigen::Vector3d position_m = Eigen::Vector3d::Zero();
  double capacity_kg = 0.0;
  double initial_kg = 0.0;
  double radius_m = 0.0;
  std::string fuel;  // "avgas" or "jet_a"
};

/// The empty aircraft plus the loads; inertia is about the empty CG in body axes.
struct MassSpec {
  double empty_mass_kg = 0.0;
  Eigen::Vector3d empty_cg_m = Eigen::Vector3d::Zero();
  InertiaSpec empty_inertia;
  std::vector<PointMassSpec> point_masses;
  std::vector<FuelTankSpec> fuel_tanks;
};

/// Operating limits; each is optional (informative: trim bounds, warnings).
struct LimitsSpec {
  std::optional<double> alpha_min_rad;
  std::optional<double> alpha_max_rad;
  std::optional<double> load_factor_min;
  std::optional<double> load_factor_max;
  std::optional<double> never_exceed_cas_mps;
  std::optional<double> max_mass_kg;
};

struct AircraftPack {
  PackMetadata metadata;
  ReferenceGeometry geometry;
  MassSpec mass;
  FlightControlsSpec flight_controls;
  AeroModelSpec aerodynamics;
  std::vector<EngineSpec> engines;
  LandingGearSpec landing_gear;
  LimitsSpec limits;
};

/// Loads and validates a pack; throws fedsim::util::ConfigError ("file:line: field: problem")
/// for anything missing, unknown, out of range or inconsistent.
AircraftPack load_aircraft_pack(const std::string& path);

/// As load_aircraft_pack, from YAML text; `origin` names the text in error messages.
AircraftPack parse_aircraft_pack(const std::string& yaml_text, const std::string& origin);

}  // namespace fedsim::flight
