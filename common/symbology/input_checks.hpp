// What every display's inputs are checked against (PFD, ND, HUD), beyond common/util's
// require_in_range(): the limits the tapes are drawn to and angles within a span.
#pragma once

#include <string_view>

namespace fedsim::symbology {

inline constexpr double kMaxSpeedMps = 400.0;     // the speed tapes' top (778 kt)
inline constexpr double kMaxVerticalMps = 150.0;  // 29 500 ft/min

/// Throws std::invalid_argument "<where>: field '<field>': ..." unless `value_rad` is finite and
/// within +-limit_deg.
void check_angle(double value_rad, double limit_deg, std::string_view where, std::string_view field);

}  // namespace fedsim::symbology
