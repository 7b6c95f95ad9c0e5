#include "common/aircraft_pack/pack_sections.hpp"

#include "common/aircraft_pack/pack_reading.hpp"
#include "common/units/units.hpp"

#include <Eigen/Eigenvalues>

#include <sstream>

namespace fedsim::aircraft_pack {

namespace {

// A rigid body's principal moments are positive and each is at most the sum of the other two.
void check_inertia(const ConfigNode& node, const InertiaSpec& inertia) {
  const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> solver(inertia.tensor());
  const Eigen::Vector3d principal = solver.eigenvalues();
  std::ostringstream values;
  values << principal.transpose();
  if (!(principal.minCoeff() > 0.0)) {
    node.fail("inertia tensor is not positive definite (principal moments " + values.str() +
              " kg m2)");
  }
  const double sum = principal.sum();
  const double tolerance = 1e-9 * sum;
  for (int i = 0; i < 3; ++i) {
    if (principal[i] > sum - principal[i] + tolerance) {
      node.fail("principal moments " + values.str() +
                " kg m2 break the triangle inequality: no rigid body has them");
    }
  }
}

InertiaSpec read_inertia(const ConfigNode& node) {
  node.reject_unknown_keys({"ixx_kgm2", "iyy_kgm2", "izz_kgm2", "ixy_kgm2", "ixz_kgm2",
                            "iyz_kgm2"});
  InertiaSpec i;
  i.ixx_kgm2 = node.number("ixx_kgm2", 0.0);
  i.iyy_kgm2 = node.number("iyy_kgm2", 0.0);
  i.izz_kgm2 = node.number("izz_kgm2", 0.0);
  i.ixy_kgm2 = node.number_or("ixy_kgm2", 0.0);
  i.ixz_kgm2 = node.number_or("ixz_kgm2", 0.0);
  i.iyz_kgm2 = node.number_or("iyz_kgm2", 0.0);
  check_inertia(node, i);
  return i;
}

PointMassSpec read_point_mass(const ConfigNode& node) {
  node.reject_unknown_keys({"name", "mass_kg", "position_m"});
  PointMassSpec p;
  p.name = node.string("name");
  p.mass_kg = node.number("mass_kg", 0.0, 1e6);
  p.position_m = read_vector3(node, "position_m");
  return p;
}

FuelTankSpec read_tank(const ConfigNode& node) {
  node.reject_unknown_keys({"name", "position_m", "capacity_kg", "initial_kg", "radius_m",
                            "fuel"});
  FuelTankSpec t;
  t.name = node.string("name");
  t.position_m = read_vector3(node, "position_m");
  t.capacity_kg = node.number("capacity_kg", 1e-6, 1e6);
  t.initial_kg = node.number("initial_kg", 0.0, 1e6);
  if (t.initial_kg > t.capacity_kg) node.fail_at("initial_kg", "exceeds capacity_kg");
  t.radius_m = node.number_or("radius_m", 0.0, 0.0, 100.0);
  t.fuel = node.choice("fuel", {"avgas", "jet_a"});
  return t;
}

std::optional<double> optional_number(const ConfigNode& node, const std::string& key,
                                      double min, double max, double scale = 1.0) {
  if (!node.has(key)) return std::nullopt;
  return node.number(key, min, max) * scale;
}

}  // namespace

void check_pack_root(const ConfigNode& root) {
  if (!root.yaml().IsMap()) root.fail("an aircraft pack is a YAML map");
  root.reject_unknown_keys({"fedsim_aircraft_pack", "metadata", "geometry", "mass",
                            "flight_controls", "aerodynamics", "propulsion", "landing_gear",
                            "limits", "stall_warning"});
  if (root.integer("fedsim_aircraft_pack", kFormatVersion, kFormatVersion) != kFormatVersion) {
    root.fail_at("fedsim_aircraft_pack", "unsupported format version");
  }
}

PackMetadata read_metadata(const ConfigNode& node) {
  node.reject_unknown_keys({"name", "source", "description", "notes"});
  PackMetadata m;
  m.name = node.string("name");
  m.source = node.string("source");
  if (m.name.empty()) node.fail_at("name", "must not be empty");
  if (m.source.empty()) node.fail_at("source", "must say where the figures come from");
  m.description = node.string_or("description", "");
  if (node.has("notes")) m.notes = node.strings("notes");
  return m;
}

ReferenceGeometry read_geometry(const ConfigNode& node) {
  node.reject_unknown_keys({"wing_area_m2", "wing_span_m", "mean_chord_m",
                            "aero_reference_point_m", "pilot_eye_point_m",
                            "visual_reference_point_m"});
  ReferenceGeometry g;
  g.wing_area_m2 = node.number("wing_area_m2", 1e-6, 1e4);
  g.wing_span_m = node.number("wing_span_m", 1e-4, 1e3);
  g.mean_chord_m = node.number("mean_chord_m", 1e-4, 1e3);
  g.aero_reference_point_m = read_vector3(node, "aero_reference_point_m");
  g.pilot_eye_point_m = read_vector3(node, "pilot_eye_point_m");
  g.visual_reference_point_m = node.has("visual_reference_point_m")
                                   ? read_vector3(node, "visual_reference_point_m")
                                   : Eigen::Vector3d::Zero();
  return g;
}

MassSpec read_mass(const ConfigNode& node) {
  node.reject_unknown_keys({"empty_mass_kg", "empty_cg_m", "empty_inertia", "point_masses",
                            "fuel_tanks"});
  MassSpec m;
  m.empty_mass_kg = node.number("empty_mass_kg", 0.0, 1e7);
  if (!(m.empty_mass_kg > 0.0)) node.fail_at("empty_mass_kg", "must be positive");
  m.empty_cg_m = read_vector3(node, "empty_cg_m");
  m.empty_inertia = read_inertia(node.child("empty_inertia"));
  if (node.has("point_masses")) {
    const auto items = node.child("point_masses").items();
    require_unique_names(items, "name");
    for (const auto& item : items) m.point_masses.push_back(read_point_mass(item));
  }
  if (node.has("fuel_tanks")) {
    const auto items = node.child("fuel_tanks").items();
    require_unique_names(items, "name");
    for (const auto& item : items) m.fuel_tanks.push_back(read_tank(item));
  }
  return m;
}

LimitsSpec read_limits(const ConfigNode& node) {
  node.reject_unknown_keys({"alpha_min_rad", "alpha_max_rad", "load_factor_min",
                            "load_factor_max", "never_exceed_cas_kt", "max_mass_kg"});
  LimitsSpec l;
  l.alpha_min_rad = optional_number(node, "alpha_min_rad", -3.2, 3.2);
  l.alpha_max_rad = optional_number(node, "alpha_max_rad", -3.2, 3.2);
  if (l.alpha_min_rad && l.alpha_max_rad && !(*l.alpha_min_rad < *l.alpha_max_rad)) {
    node.fail_at("alpha_max_rad", "must exceed alpha_min_rad");
  }
  l.load_factor_min = optional_number(node, "load_factor_min", -20.0, 0.0);
  l.load_factor_max = optional_number(node, "load_factor_max", 0.0, 20.0);
  l.never_exceed_cas_mps = optional_number(node, "never_exceed_cas_kt", 1.0, 5000.0, units::kKtToMps);
  l.max_mass_kg = optional_number(node, "max_mass_kg", 0.0, 1e7);
  return l;
}

std::optional<StallWarningSpec> read_stall_warning(const ConfigNode& root) {
  if (!root.has("stall_warning")) return std::nullopt;
  const ConfigNode node = root.child("stall_warning");
  node.reject_unknown_keys({"flap_norm", "alpha_rad"});
  StallWarningSpec s;
  s.flap_norm = read_breakpoints(node, "flap_norm");
  if (s.flap_norm.front() < 0.0 || s.flap_norm.back() > 1.0) node.fail_at("flap_norm", "flap settings lie in [0, 1]");
  s.alpha_rad = node.numbers("alpha_rad", s.flap_norm.size());
  for (const double alpha : s.alpha_rad) {
    if (!(alpha >= 0.0 && alpha <= 1.0)) node.fail_at("alpha_rad", "each angle of attack in [0, 1] rad");
  }
  return s;
}

}  // namespace fedsim::aircraft_pack
