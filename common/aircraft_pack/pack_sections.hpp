// The sections of an aircraft pack (data/aircraft/README.md) that every user of a pack reads,
// and the pack's top level: metadata, reference geometry (the pilot's eye point among it), mass
// (the empty aircraft and its loads), limits and the stall-warning schedule. The flight model's
// loader (federates/flight/model/aircraft) reads them through these functions and adds its own
// sections; pack_facts.hpp reads them alone, for the federates that need a pack's facts without
// a flight model (the image generator's eye point, the control loader's stick shaker).
#pragma once

#include "common/util/config_node.hpp"

#include <Eigen/Dense>

#include <optional>
#include <string>
#include <vector>

namespace fedsim::aircraft_pack {

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

/// The stick shaker's schedule: the angle of attack where the stall warning begins at each flap
/// setting (linear between them), as the pack states it. The flight model checks it against the
/// pack's own lift when it loads the pack: the angle where the lift coefficient first reaches
/// CL_max / 1.05^2 (federates/flight/model/aircraft/stall_warning.hpp).
struct StallWarningSpec {
  std::vector<double> flap_norm;  // 0..1, strictly increasing
  std::vector<double> alpha_rad;  // one per flap setting [rad]
};

/// The pack format's version (`fedsim_aircraft_pack:`).
inline constexpr int kFormatVersion = 1;

/// A pack's top level: a YAML map of the known sections only, of this format version. Throws
/// util::ConfigError ("file:line: field: problem").
void check_pack_root(const util::ConfigNode& root);

// Section readers: each throws util::ConfigError naming the file, line and field of the first
// figure missing, unknown, out of range or inconsistent.
PackMetadata read_metadata(const util::ConfigNode& node);
ReferenceGeometry read_geometry(const util::ConfigNode& node);
MassSpec read_mass(const util::ConfigNode& node);
LimitsSpec read_limits(const util::ConfigNode& node);
/// The root's optional `stall_warning` section (nullopt without one).
std::optional<StallWarningSpec> read_stall_warning(const util::ConfigNode& root);

}  // namespace fedsim::aircraft_pack
