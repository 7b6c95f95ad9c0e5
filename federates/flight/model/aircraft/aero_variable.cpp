// Names of the aerodynamic input variables, as written in aircraft packs.
#include "flight/model/aircraft/aero_variable.hpp"

#include <array>

namespace fedsim::flight {

namespace {
// Same order as the enum; a static_assert below keeps the two in step.
constexpr std::array<std::string_view, kAeroVariableCount> kNames = {
    "alpha_rad",        "abs_alpha_rad",    "beta_rad",         "abs_beta_rad",
    "mach",             "qbar_pa",          "p_hat",            "q_hat",
    "r_hat",            "alphadot_hat",     "betadot_hat",      "elevator_rad",
    "abs_elevator_rad", "aileron_rad",      "abs_aileron_rad",  "rudder_rad",
    "abs_rudder_rad",   "flap_norm",        "flap_deg",         "gear_norm",
    "speedbrake_norm",  "spoiler_norm",     "h_over_b",         "stall_hysteresis",
    "cl_squared"};
static_assert(kNames.size() == kAeroVariableCount);
}  // namespace

std::string_view aero_variable_name(AeroVariable v) { return kNames.at(slot_of(v)); }

std::optional<AeroVariable> aero_variable_from_name(std::string_view name) {
  for (std::size_t i = 0; i < kNames.size(); ++i) {
    if (kNames[i] == name) return static_cast<AeroVariable>(i);
  }
  return std::nullopt;
}

std::string aero_variable_names() {
  std::string out;
  for (const auto name : kNames) {
    if (!out.empty()) out += ", ";
    out += name;
  }
  return out;
}

}  // namespace fedsim::flight
