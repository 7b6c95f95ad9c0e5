// Aircraft-pack loader: flight controls, propulsion and landing-gear sections.
#include <algorithm>
#include <cmath>

#include "flight/model/aircraft/pack_reading.hpp"
#include "flight/model/systems/propeller.hpp"

namespace fedsim::flight::pack_detail {

namespace {

// Unit conversions of the pack's non-SI keys (names say the unit).
constexpr double kKwhToJ = 3.6e6;
constexpr double kHourToS = 3600.0;

SurfaceActuatorSpec read_surface(const ConfigNode& node) {
  node.reject_unknown_keys({"deflection_at_plus_one_deg", "deflection_at_minus_one_deg",
                            "min_deflection_deg", "max_deflection_deg", "time_constant_s",
                            "rate_limit_deg_per_s"});
  SurfaceActuatorSpec s;
  s.deflection_at_plus_one_rad = node.number("deflection_at_plus_one_deg", -90, 90) * units::kDegToRad;
  s.deflection_at_minus_one_rad = node.number("deflection_at_minus_one_deg", -90, 90) * units::kDegToRad;
  const double plus = s.deflection_at_plus_one_rad;
  const double minus = s.deflection_at_minus_one_rad;
  if (plus * minus > 0.0 || (plus == 0.0 && minus == 0.0)) {
    node.fail_at("deflection_at_minus_one_deg",
                 "commands +1 and -1 must deflect the surface to opposite sides");
  }
  const double low = std::min(plus, minus);
  const double high = std::max(plus, minus);
  s.min_deflection_rad = node.number_or("min_deflection_deg", low / units::kDegToRad, -90, 0) * units::kDegToRad;
  s.max_deflection_rad = node.number_or("max_deflection_deg", high / units::kDegToRad, 0, 90) * units::kDegToRad;
  if (!(s.min_deflection_rad < s.max_deflection_rad)) {
    node.fail_at("max_deflection_deg", "must exceed min_deflection_deg");
  }
  s.time_constant_s = node.number_or("time_constant_s", 0.0, 0.0, 10.0);
  s.rate_limit_radps = node.number_or("rate_limit_deg_per_s", 0.0, 0.0, 1000.0) * units::kDegToRad;
  return s;
}

KinematicSurfaceSpec read_kinematic(const ConfigNode& node, bool allow_travel) {
  std::vector<std::string> allowed = {"positions_norm", "transit_times_s"};
  if (allow_travel) allowed.push_back("full_travel_deg");
  node.reject_unknown_keys(allowed);
  KinematicSurfaceSpec k;
  k.positions_norm = read_breakpoints(node, "positions_norm");
  if (k.positions_norm.size() < 2 || k.positions_norm.front() != 0.0 ||
      k.positions_norm.back() != 1.0) {
    node.fail_at("positions_norm", "positions must run from 0 to 1 (at least two of them)");
  }
  k.transit_times_s = node.numbers("transit_times_s", k.positions_norm.size() - 1);
  const auto times = node.child("transit_times_s").items();
  for (std::size_t i = 0; i < times.size(); ++i) {
    if (k.transit_times_s[i] < 0.0) times[i].fail("a transit time cannot be negative");
  }
  if (allow_travel) k.full_travel_rad = node.number_or("full_travel_deg", 0.0, 0.0, 90.0) * units::kDegToRad;
  return k;
}

// Optional-section helpers.
std::optional<SurfaceActuatorSpec> surface_if(const ConfigNode& section, const char* key) {
  if (!section.has(key)) return std::nullopt;
  return read_surface(section.child(key));
}
std::optional<KinematicSurfaceSpec> kinematic_if(const ConfigNode& section, const char* key,
                                                 bool allow_travel) {
  if (!section.has(key)) return std::nullopt;
  return read_kinematic(section.child(key), allow_travel);
}

PistonEngineSpec read_piston(const ConfigNode& node) {
  node.reject_unknown_keys({"max_power_w", "displacement_m3", "idle_rpm", "max_rpm",
                            "min_manifold_pressure_pa", "max_manifold_pressure_pa",
                            "bsfc_kg_per_kwh", "strokes", "min_throttle", "max_throttle",
                            "single_magneto_power_loss"});
  PistonEngineSpec p;
  p.max_power_w = node.number("max_power_w", 1.0, 1e7);
  p.displacement_m3 = node.number("displacement_m3", 1e-5, 1.0);
  p.idle_rpm = node.number("idle_rpm", 1.0, 1e5);
  p.max_rpm = node.number("max_rpm", 1.0, 1e5);
  if (!(p.idle_rpm < p.max_rpm)) node.fail_at("max_rpm", "must exceed idle_rpm");
  p.min_manifold_pressure_pa = node.number("min_manifold_pressure_pa", 0.0, 5e5);
  p.max_manifold_pressure_pa = node.number("max_manifold_pressure_pa", 0.0, 5e5);
  if (!(p.min_manifold_pressure_pa < p.max_manifold_pressure_pa)) {
    node.fail_at("max_manifold_pressure_pa", "must exceed min_manifold_pressure_pa");
  }
  p.bsfc_kg_per_ws = node.number("bsfc_kg_per_kwh", 0.0, 10.0) / kKwhToJ;
  p.strokes = node.integer("strokes", 2, 4);
  if (p.strokes == 3) node.fail_at("strokes", "must be 2 or 4");
  p.min_throttle = node.number_or("min_throttle", 0.0, 0.0, 1.0);
  p.max_throttle = node.number_or("max_throttle", 1.0, 0.0, 1.0);
  if (!(p.min_throttle < p.max_throttle)) node.fail_at("max_throttle", "must exceed min_throttle");
  p.single_magneto_power_loss = node.number_or("single_magneto_power_loss", 0.0, 0.0, 1.0);
  return p;
}

// CT or CP: 1-D in advance ratio, or 2-D in advance ratio and blade pitch (degrees in the pack).
void read_propeller_coefficient(const ConfigNode& node, const std::string& key, Table1D& fixed,
                                Table2D& variable) {
  if (node.child(key).has("column")) {
    const Table2D deg = read_table_2d(node, key, "advance_ratio", "blade_pitch_deg");
    std::vector<double> pitch_rad = deg.cols();
    for (double& p : pitch_rad) p *= units::kDegToRad;
    variable = Table2D(deg.rows(), pitch_rad, deg.values());
  } else {
    fixed = read_table_1d(node, key, "advance_ratio");
  }
}

PropellerSpec read_propeller(const ConfigNode& node) {
  node.reject_unknown_keys({"diameter_m", "blade_count", "inertia_kgm2", "gear_ratio",
                            "min_pitch_deg", "max_pitch_deg", "spin_sense", "p_factor_m_per_rad",
                            "thrust_coefficient", "power_coefficient", "thrust_coefficient_factor",
                            "power_coefficient_factor", "factor_fade_start_advance_ratio",
                            "factor_fade_end_advance_ratio", "thrust_tip_mach_factor",
                            "power_tip_mach_factor"});
  PropellerSpec p;
  p.diameter_m = node.number("diameter_m", 0.1, 10.0);
  p.blade_count = node.integer("blade_count", 1, 12);
  p.inertia_kgm2 = node.number("inertia_kgm2", 1e-6, 1e4);
  p.gear_ratio = node.number_or("gear_ratio", 1.0, 0.05, 20.0);
  p.min_pitch_rad = node.number("min_pitch_deg", -90.0, 90.0) * units::kDegToRad;
  p.max_pitch_rad = node.number("max_pitch_deg", -90.0, 90.0) * units::kDegToRad;
  if (p.max_pitch_rad < p.min_pitch_rad) node.fail_at("max_pitch_deg", "below min_pitch_deg");
  p.spin_sense = node.integer("spin_sense", -1, 1);
  if (p.spin_sense == 0) node.fail_at("spin_sense", "must be +1 or -1");
  p.p_factor_m_per_rad = node.number_or("p_factor_m_per_rad", 0.0, -10.0, 10.0);
  read_propeller_coefficient(node, "thrust_coefficient", p.thrust_coefficient,
                             p.thrust_coefficient_pitch);
  read_propeller_coefficient(node, "power_coefficient", p.power_coefficient,
                             p.power_coefficient_pitch);
  p.thrust_coefficient_factor =
      node.number_or("thrust_coefficient_factor", 1.0, Propeller::kMinCoefficientFactor,
                     Propeller::kMaxCoefficientFactor);
  p.power_coefficient_factor =
      node.number_or("power_coefficient_factor", 1.0, Propeller::kMinCoefficientFactor,
                     Propeller::kMaxCoefficientFactor);
  // The fade band: both ends or neither.
  const bool has_start = node.has("factor_fade_start_advance_ratio");
  const bool has_end = node.has("factor_fade_end_advance_ratio");
  if (has_start != has_end) {
    node.fail_at(has_start ? "factor_fade_start_advance_ratio" : "factor_fade_end_advance_ratio",
                 std::string("needs factor_fade_") + (has_start ? "end" : "start") +
                     "_advance_ratio too (a fade band has two ends)");
  }
  if (has_start) {
    PropellerSpec::FactorFade fade;
    fade.start_advance_ratio = node.number("factor_fade_start_advance_ratio", 0.0,
                                           Propeller::kMaxFadeAdvanceRatio);
    fade.end_advance_ratio =
        node.number("factor_fade_end_advance_ratio", 0.0, Propeller::kMaxFadeAdvanceRatio);
    if (!(fade.end_advance_ratio > fade.start_advance_ratio)) {
      node.fail_at("factor_fade_end_advance_ratio",
                   "must exceed factor_fade_start_advance_ratio (" +
                       std::to_string(fade.start_advance_ratio) + ")");
    }
    p.factor_fade = fade;
  }
  if (node.has("thrust_tip_mach_factor")) {
    p.thrust_tip_mach_factor = read_table_1d(node, "thrust_tip_mach_factor", "tip_mach");
  }
  if (node.has("power_tip_mach_factor")) {
    p.power_tip_mach_factor = read_table_1d(node, "power_tip_mach_factor", "tip_mach");
  }
  return p;
}

TurbofanSpec read_turbofan(const ConfigNode& node) {
  node.reject_unknown_keys({"max_thrust_n", "bypass_ratio", "tsfc_kg_per_n_h", "tsfc_per_mach",
                            "min_fuel_flow_kg_per_s", "bleed_fraction", "idle_n1_pct",
                            "idle_n2_pct", "max_n1_pct", "max_n2_pct",
                            "n1_spool_up_time_constant_s", "n1_spool_down_time_constant_s",
                            "n2_spool_up_time_constant_s", "n2_spool_down_time_constant_s",
                            "idle_thrust_fraction", "max_thrust_fraction"});
  TurbofanSpec t;
  t.max_thrust_n = node.number("max_thrust_n", 1.0, 1e7);
  t.bypass_ratio = node.number("bypass_ratio", 0.0, 30.0);
  t.tsfc_kg_per_ns = node.number("tsfc_kg_per_n_h", 1e-6, 1.0) / kHourToS;
  t.tsfc_per_mach = node.number_or("tsfc_per_mach", 0.0, 0.0, 10.0);
  t.min_fuel_flow_kgps = node.number_or("min_fuel_flow_kg_per_s", 0.0, 0.0, 100.0);
  t.bleed_fraction = node.number_or("bleed_fraction", 0.0, 0.0, 0.5);
  t.idle_n1_pct = node.number("idle_n1_pct", 1.0, 120.0);
  t.idle_n2_pct = node.number("idle_n2_pct", 1.0, 120.0);
  t.max_n1_pct = node.number_or("max_n1_pct", 100.0, 1.0, 120.0);
  t.max_n2_pct = node.number_or("max_n2_pct", 100.0, 1.0, 120.0);
  if (!(t.idle_n1_pct < t.max_n1_pct)) node.fail_at("max_n1_pct", "must exceed idle_n1_pct");
  if (!(t.idle_n2_pct < t.max_n2_pct)) node.fail_at("max_n2_pct", "must exceed idle_n2_pct");
  t.n1_spool_up_time_constant_s = node.number("n1_spool_up_time_constant_s", 1e-3, 100.0);
  t.n1_spool_down_time_constant_s = node.number("n1_spool_down_time_constant_s", 1e-3, 100.0);
  t.n2_spool_up_time_constant_s = node.number("n2_spool_up_time_constant_s", 1e-3, 100.0);
  t.n2_spool_down_time_constant_s = node.number("n2_spool_down_time_constant_s", 1e-3, 100.0);
  t.idle_thrust_fraction = read_table_2d(node, "idle_thrust_fraction", "mach",
                                         "density_altitude_m");
  t.max_thrust_fraction = read_table_2d(node, "max_thrust_fraction", "mach",
                                        "density_altitude_m");
  return t;
}

EngineSpec read_engine(const ConfigNode& node, std::size_t tank_count) {
  const std::string type = node.choice("type", {"piston_propeller", "turbofan"});
  EngineSpec e;
  e.type = type == "turbofan" ? EngineType::turbofan : EngineType::piston_propeller;
  if (e.type == EngineType::turbofan) {
    node.reject_unknown_keys({"name", "type", "position_m", "orientation_deg", "fuel_tanks",
                              "turbofan"});
  } else {
    node.reject_unknown_keys({"name", "type", "position_m", "orientation_deg", "fuel_tanks",
                              "piston", "propeller"});
  }
  e.name = node.string("name");
  e.position_m = read_vector3(node, "position_m");
  if (node.has("orientation_deg")) e.orientation_rad = read_vector3(node, "orientation_deg") * units::kDegToRad;
  {
    const auto items = node.child("fuel_tanks").items();
    if (items.empty()) node.fail_at("fuel_tanks", "an engine needs at least one fuel tank");
    for (const auto& item : items) {
      const double index = item.as_number();
      if (index != std::floor(index) || index < 0 || index >= static_cast<double>(tank_count)) {
        item.fail("no fuel tank with index " + item.as_string() + " (the pack has " +
                  std::to_string(tank_count) + ")");
      }
      e.fuel_tanks.push_back(static_cast<int>(index));
    }
  }
  if (e.type == EngineType::turbofan) {
    e.turbofan = read_turbofan(node.child("turbofan"));
  } else {
    e.piston = read_piston(node.child("piston"));
    e.propeller = read_propeller(node.child("propeller"));
  }
  return e;
}

GearContactSpec read_contact(const ConfigNode& node) {
  node.reject_unknown_keys({"name", "type", "position_m", "spring_n_per_m", "damping_n_s_per_m",
                            "rebound_damping_n_s_per_m", "static_friction", "dynamic_friction",
                            "rolling_friction", "max_steer_deg", "brake_group", "retractable"});
  GearContactSpec c;
  c.name = node.string("name");
  c.type = node.choice("type", {"wheel", "structure"}) == "wheel" ? ContactType::wheel
                                                                  : ContactType::structure;
  c.position_m = read_vector3(node, "position_m");
  c.spring_n_per_m = node.number("spring_n_per_m", 1e-3, 1e10);
  c.damping_n_s_per_m = node.number("damping_n_s_per_m", 0.0, 1e10);
  c.rebound_damping_n_s_per_m =
      node.number_or("rebound_damping_n_s_per_m", c.damping_n_s_per_m, 0.0, 1e10);
  c.static_friction = node.number("static_friction", 0.0, 5.0);
  c.dynamic_friction = node.number("dynamic_friction", 0.0, 5.0);
  c.rolling_friction = node.number_or("rolling_friction", 0.0, 0.0, 5.0);
  c.max_steer_rad = node.number_or("max_steer_deg", 0.0, 0.0, 180.0) * units::kDegToRad;
  const std::string brake = node.choice_or("brake_group", {"none", "left", "right"}, "none");
  c.brake_group = brake == "left"    ? BrakeGroup::left
                  : brake == "right" ? BrakeGroup::right
                                     : BrakeGroup::none;
  c.retractable = node.boolean_or("retractable", false);
  if (c.type == ContactType::structure && (c.retractable || c.max_steer_rad > 0.0 ||
                                           c.brake_group != BrakeGroup::none)) {
    node.fail_at("type", "a structure contact cannot retract, steer or brake");
  }
  return c;
}

YawDamperSpec read_yaw_damper(const ConfigNode& node) {
  node.reject_unknown_keys({"gain_per_radps", "washout_time_constant_s", "authority", "engaged_at_start"});
  YawDamperSpec y;
  y.gain_per_radps = read_table_1d(node, "gain_per_radps", "mach");
  for (double k : y.gain_per_radps.values()) {
    if (!(std::abs(k) <= 100.0)) node.fail_at("gain_per_radps", "gains must be finite, |K| <= 100 per rad/s");
  }
  y.washout_time_constant_s = node.number_or("washout_time_constant_s", 0.0, 0.0, 100.0);
  y.authority = node.number_or("authority", 1.0, 0.0, 1.0);
  if (!(y.authority > 0.0)) node.fail_at("authority", "must be positive");
  y.engaged_at_start = node.boolean_or("engaged_at_start", true);
  return y;
}

PitchTrimSpec read_pitch_trim(const ConfigNode& node) {
  node.reject_unknown_keys({"kind", "rate_per_s"});
  PitchTrimSpec t;
  t.kind = node.choice("kind", {"stabiliser", "tab"}) == "stabiliser" ? PitchTrimKind::kStabiliser
                                                                      : PitchTrimKind::kTab;
  t.rate_per_s = node.number("rate_per_s", 0.0, 10.0);
  if (!(t.rate_per_s > 0.0)) node.fail_at("rate_per_s", "must be positive");
  return t;
}

WingLevellerSpec read_wing_leveller(const ConfigNode& node) {
  node.reject_unknown_keys({"bank_gain_per_rad", "bank_integral_gain_per_rad_s",
                            "bank_rate_gain_per_radps", "airborne_only", "engaged_at_start"});
  WingLevellerSpec w;
  // |K| <= 1000: far beyond any aileron gain an aircraft flies (the C172's is 50 per rad).
  w.bank_gain_per_rad = node.number("bank_gain_per_rad", -1000.0, 1000.0);
  w.bank_integral_gain_per_rad_s = node.number_or("bank_integral_gain_per_rad_s", 0.0, -1000.0, 1000.0);
  w.bank_rate_gain_per_radps = node.number_or("bank_rate_gain_per_radps", 0.0, -1000.0, 1000.0);
  w.airborne_only = node.boolean_or("airborne_only", true);
  w.engaged_at_start = node.boolean_or("engaged_at_start", false);
  return w;
}

}  // namespace

FlightControlsSpec read_flight_controls(const ConfigNode& section) {
  section.reject_unknown_keys({"elevator", "aileron", "rudder", "flaps", "speedbrake",
                               "spoilers", "yaw_damper", "pitch_trim", "wing_leveller"});
  FlightControlsSpec out;
  out.elevator = surface_if(section, "elevator");
  out.aileron = surface_if(section, "aileron");
  out.rudder = surface_if(section, "rudder");
  out.flaps = kinematic_if(section, "flaps", true);
  out.speedbrake = kinematic_if(section, "speedbrake", false);
  out.spoilers = kinematic_if(section, "spoilers", false);
  if (section.has("yaw_damper")) {
    if (!out.rudder) section.fail_at("yaw_damper", "a yaw damper needs a rudder");
    out.yaw_damper = read_yaw_damper(section.child("yaw_damper"));
  }
  if (section.has("pitch_trim")) {
    if (!out.elevator) section.fail_at("pitch_trim", "a pitch trim needs an elevator");
    out.pitch_trim = read_pitch_trim(section.child("pitch_trim"));
  }
  if (section.has("wing_leveller")) {
    if (!out.aileron) section.fail_at("wing_leveller", "a wing leveller needs an aileron");
    out.wing_leveller = read_wing_leveller(section.child("wing_leveller"));
  }
  return out;
}

std::vector<EngineSpec> read_propulsion(const ConfigNode& section, const aircraft_pack::MassSpec& mass) {
  section.reject_unknown_keys({"engines"});
  const auto items = section.child("engines").items();
  require_unique_names(items, "name");
  std::vector<EngineSpec> out;
  for (const auto& item : items) out.push_back(read_engine(item, mass.fuel_tanks.size()));
  return out;
}

LandingGearSpec read_landing_gear(const ConfigNode& section) {
  section.reject_unknown_keys({"transit_time_s", "contacts"});
  LandingGearSpec out;
  out.transit_time_s = section.number_or("transit_time_s", 0.0, 0.0, 120.0);
  const auto items = section.child("contacts").items();
  require_unique_names(items, "name");
  for (const auto& item : items) out.contacts.push_back(read_contact(item));
  const bool any_retractable = std::any_of(out.contacts.begin(), out.contacts.end(),
                                           [](const auto& c) { return c.retractable; });
  if (any_retractable && !(out.transit_time_s > 0.0)) {
    section.fail_at("transit_time_s", "retractable contacts need a positive transit time");
  }
  return out;
}

}  // namespace fedsim::flight::pack_detail
