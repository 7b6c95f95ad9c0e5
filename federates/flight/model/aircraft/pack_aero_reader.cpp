// Aircraft-pack loader: the aerodynamics section (factors and coefficient terms per axis).
#include <map>

#include "flight/model/aircraft/aero_variable.hpp"
#include "flight/model/aircraft/pack_reading.hpp"

namespace fedsim::flight::pack_detail {

namespace {

// Which names a term may use where: factors may read variables only; lift terms may not read
// cl_squared (it is the result of the lift axis); every other term may read all of them.
struct NameScope {
  const std::map<std::string, std::size_t>* factor_slots = nullptr;
  bool allow_factors = false;
  bool allow_cl_squared = false;
  bool has_stall_hysteresis = false;
};

// A variable that only means something when the pack defines the control behind it.
void require_control_for(AeroVariable v, const FlightControlsSpec& controls,
                         const ConfigNode& where) {
  auto missing = [&](const char* surface) {
    where.fail("'" + std::string(aero_variable_name(v)) + "' needs flight_controls." + surface +
               ", which this pack does not define");
  };
  switch (v) {
    case AeroVariable::elevator_rad:
    case AeroVariable::abs_elevator_rad:
      if (!controls.elevator) missing("elevator");
      break;
    case AeroVariable::aileron_rad:
    case AeroVariable::abs_aileron_rad:
      if (!controls.aileron) missing("aileron");
      break;
    case AeroVariable::rudder_rad:
    case AeroVariable::abs_rudder_rad:
      if (!controls.rudder) missing("rudder");
      break;
    case AeroVariable::flap_norm:
      if (!controls.flaps) missing("flaps");
      break;
    case AeroVariable::flap_deg:
      if (!controls.flaps || !(controls.flaps->full_travel_rad > 0.0)) {
        missing("flaps with full_travel_deg");
      }
      break;
    case AeroVariable::speedbrake_norm:
      if (!controls.speedbrake) missing("speedbrake");
      break;
    case AeroVariable::spoiler_norm:
      if (!controls.spoilers) missing("spoilers");
      break;
    default:
      break;
  }
}

std::size_t resolve_name(const ConfigNode& name_node, const NameScope& scope,
                         const FlightControlsSpec& controls) {
  const std::string name = name_node.as_string();
  if (const auto v = aero_variable_from_name(name)) {
    if (*v == AeroVariable::cl_squared && !scope.allow_cl_squared) {
      name_node.fail("'cl_squared' is the result of the lift axis: lift terms and factors "
                     "cannot use it");
    }
    if (*v == AeroVariable::stall_hysteresis && !scope.has_stall_hysteresis) {
      name_node.fail("'stall_hysteresis' needs aerodynamics.stall_hysteresis limits");
    }
    require_control_for(*v, controls, name_node);
    return slot_of(*v);
  }
  if (scope.factor_slots) {
    const auto it = scope.factor_slots->find(name);
    if (it != scope.factor_slots->end()) {
      if (!scope.allow_factors) name_node.fail("a factor cannot use another factor ('" + name + "')");
      return it->second;
    }
  }
  name_node.fail("unknown variable '" + name + "' (known: " + aero_variable_names() +
                 (scope.factor_slots && !scope.factor_slots->empty() ? ", or a factor name" : "") +
                 ")");
}

AeroLookup read_lookup_table(const ConfigNode& table_node, const NameScope& scope,
                             const FlightControlsSpec& controls) {
  ParsedTable t = read_table(table_node);
  std::vector<std::size_t> slots;
  for (const auto& node : t.input_nodes) slots.push_back(resolve_name(node, scope, controls));
  switch (t.dimensions) {
    case 1:
      return AeroLookup::table(slots[0], Table1D(std::move(t.breakpoints[0]),
                                                 std::move(t.values)));
    case 2:
      return AeroLookup::table(slots[0], slots[1],
                               Table2D(std::move(t.breakpoints[0]), std::move(t.breakpoints[1]),
                                       std::move(t.values)));
    default:
      return AeroLookup::table(slots[0], slots[1], slots[2], std::move(t.breakpoints[0]),
                               std::move(t.breakpoints[1]), std::move(t.breakpoints[2]),
                               std::move(t.values));
  }
}

AeroTerm read_term(const ConfigNode& node, const NameScope& scope,
                   const FlightControlsSpec& controls) {
  node.reject_unknown_keys({"name", "description", "value", "table", "multiply_by"});
  AeroTerm term;
  term.name = node.string("name");
  term.description = node.string_or("description", "");
  const bool has_value = node.has("value");
  const bool has_table = node.has("table");
  if (has_value == has_table) node.fail("a term needs exactly one of 'value' or 'table'");
  term.lookup = has_value ? AeroLookup::constant(node.number("value"))
                          : read_lookup_table(node.child("table"), scope, controls);
  if (node.has("multiply_by")) {
    for (const auto& item : node.child("multiply_by").items()) {
      term.multiplier_slots.push_back(resolve_name(item, scope, controls));
    }
  }
  return term;
}

std::vector<AeroTerm> read_terms(const ConfigNode& list, const NameScope& scope,
                                 const FlightControlsSpec& controls) {
  const auto items = list.items();
  require_unique_names(items, "name");
  std::vector<AeroTerm> out;
  for (const auto& item : items) out.push_back(read_term(item, scope, controls));
  return out;
}

std::optional<StallHysteresisSpec> read_stall_hysteresis(const ConfigNode& section) {
  if (!section.has("stall_hysteresis")) return std::nullopt;
  const ConfigNode node = section.child("stall_hysteresis");
  node.reject_unknown_keys({"alpha_set_rad", "alpha_clear_rad"});
  StallHysteresisSpec out;
  out.alpha_set_rad = node.number("alpha_set_rad", -3.2, 3.2);
  out.alpha_clear_rad = node.number("alpha_clear_rad", -3.2, 3.2);
  if (!(out.alpha_clear_rad < out.alpha_set_rad)) {
    node.fail_at("alpha_clear_rad", "must be below alpha_set_rad");
  }
  return out;
}

// Factor names become slots after the variables; a name may not shadow a variable.
std::map<std::string, std::size_t> factor_slots_of(const ConfigNode& list) {
  const auto items = list.items();
  if (items.size() > AeroModelSpec::kMaxFactors) {
    list.fail("at most " + std::to_string(AeroModelSpec::kMaxFactors) + " factors");
  }
  std::map<std::string, std::size_t> slots;
  for (const auto& item : items) {
    const std::string name = item.string("name");
    if (aero_variable_from_name(name)) {
      item.fail_at("name", "'" + name + "' is a variable name; choose another factor name");
    }
    slots.emplace(name, kAeroVariableCount + slots.size());
  }
  return slots;
}

}  // namespace

AeroModelSpec read_aerodynamics(const ConfigNode& section, const FlightControlsSpec& controls) {
  std::vector<std::string> allowed = {"stall_hysteresis", "factors"};
  for (std::size_t i = 0; i < kAeroAxisCount; ++i) {
    allowed.emplace_back(aero_axis_name(static_cast<AeroAxis>(i)));
  }
  section.reject_unknown_keys(allowed);

  AeroModelSpec out;
  out.stall_hysteresis = read_stall_hysteresis(section);
  std::map<std::string, std::size_t> factor_slots;
  if (section.has("factors")) {
    factor_slots = factor_slots_of(section.child("factors"));
    const NameScope scope{&factor_slots, false, false, out.stall_hysteresis.has_value()};
    out.factors = read_terms(section.child("factors"), scope, controls);
  }
  for (std::size_t i = 0; i < kAeroAxisCount; ++i) {
    const auto axis = static_cast<AeroAxis>(i);
    const NameScope scope{&factor_slots, true, axis != AeroAxis::lift,
                          out.stall_hysteresis.has_value()};
    out.axes[i] = read_terms(section.child(std::string(aero_axis_name(axis))), scope, controls);
  }
  return out;
}

}  // namespace fedsim::flight::pack_detail
