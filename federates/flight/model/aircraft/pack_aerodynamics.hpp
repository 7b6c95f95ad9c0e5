// Aerodynamics section of an aircraft pack: coefficient terms per axis and named factors.
#pragma once

#include <array>
#include <cstddef>
#include <optional>
#include <string_view>
#include <vector>

#include "flight/model/aircraft/aero_term.hpp"

namespace fedsim::flight {

/// The six coefficient axes. Lift, drag and side force are wind-axis coefficients (lift along
/// -z_wind, drag along -x_wind, side force along +y_wind); roll, pitch and yaw moments are
/// body-axis coefficients about the aero reference point.
enum class AeroAxis : std::size_t { lift, drag, side_force, roll_moment, pitch_moment, yaw_moment };
inline constexpr std::size_t kAeroAxisCount = 6;

/// Pack spelling of an axis, e.g. "side_force".
std::string_view aero_axis_name(AeroAxis axis);

/// JSBSim-style stall hysteresis: the flag sets when alpha rises above `alpha_set_rad` and
/// clears when alpha falls below `alpha_clear_rad`.
struct StallHysteresisSpec {
  double alpha_set_rad = 0.0;
  double alpha_clear_rad = 0.0;
};

/// Factors fill the slots after the AeroVariable ones (factor i -> kAeroVariableCount + i);
/// they may read variables only (not other factors, not cl_squared).
struct AeroModelSpec {
  static constexpr std::size_t kMaxFactors = 16;
  std::vector<AeroTerm> factors;
  std::array<std::vector<AeroTerm>, kAeroAxisCount> axes;
  std::optional<StallHysteresisSpec> stall_hysteresis;

  const std::vector<AeroTerm>& terms(AeroAxis axis) const {
    return axes[static_cast<std::size_t>(axis)];
  }
};

}  // namespace fedsim::flight
