// The fixed vocabulary of named inputs that aerodynamic terms in an aircraft pack may use.
#pragma once

#include <cstddef>
#include <optional>
#include <string>
#include <string_view>

namespace fedsim::flight {

/// A quantity the aerodynamic model computes before it sums the coefficient terms. Its value is
/// stored in a slot (the enum's index); pack-defined factors follow these slots. The pack names
/// them by the strings of aero_variable_name(); units are in the names.
enum class AeroVariable : std::size_t {
  alpha_rad,         // angle of attack
  abs_alpha_rad,     // |alpha|
  beta_rad,          // angle of sideslip (positive: air from the right)
  abs_beta_rad,      // |beta|
  mach,              // Mach number
  qbar_pa,           // dynamic pressure
  p_hat,             // p b / (2 V), roll rate relative to the air mass
  q_hat,             // q c / (2 V)
  r_hat,             // r b / (2 V)
  alphadot_hat,      // alphadot c / (2 V)
  betadot_hat,       // betadot b / (2 V)
  elevator_rad,      // trailing edge down positive
  abs_elevator_rad,  // |elevator|
  aileron_rad,       // differential aileron, positive gives right-wing-down roll
  abs_aileron_rad,   // |aileron|
  rudder_rad,        // trailing edge left positive (nose-left yaw)
  abs_rudder_rad,    // |rudder|
  flap_norm,         // 0 (up) .. 1 (full travel)
  flap_deg,          // flap_norm times the pack's full flap travel
  gear_norm,         // 0 (up) .. 1 (down and locked)
  speedbrake_norm,   // 0 .. 1
  spoiler_norm,      // ground spoilers, 0 .. 1
  h_over_b,          // height of the aero reference point above ground / wing span
  stall_hysteresis,  // 0 or 1, see Aerodynamics
  cl_squared,        // square of this evaluation's total CL (not for lift terms or factors)
  count              // number of variables, not a variable
};

inline constexpr std::size_t kAeroVariableCount = static_cast<std::size_t>(AeroVariable::count);

/// Slot index of a variable.
constexpr std::size_t slot_of(AeroVariable v) { return static_cast<std::size_t>(v); }

/// The pack spelling of a variable, e.g. "alpha_rad".
std::string_view aero_variable_name(AeroVariable v);

/// The variable spelled `name`, or nothing if the name is not in the vocabulary.
std::optional<AeroVariable> aero_variable_from_name(std::string_view name);

/// All names, comma separated (for error messages and documentation).
std::string aero_variable_names();

}  // namespace fedsim::flight
