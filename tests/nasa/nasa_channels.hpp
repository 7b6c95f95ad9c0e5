// The channels compared between fedsim and the NASA check cases (SI units) and their groups.
#pragma once

#include <array>
#include <string_view>

namespace fedsim::flight::nasa {

/// A compared quantity. north_m / east_m are latitude and longitude times the WGS-84 equatorial
/// radius (times cos(lat0) for east): arc lengths from the equator/meridian, so that position
/// tolerances read in metres.
struct Channel {
  std::string_view name;
  std::string_view group;
  bool is_angle;  // wraps at +-pi: compared modulo 2 pi
};

inline constexpr std::array<Channel, 12> kChannels = {{
    {"altitude_m", "altitude", false},
    {"north_m", "position", false},
    {"east_m", "position", false},
    {"v_north_mps", "velocity", false},
    {"v_east_mps", "velocity", false},
    {"v_down_mps", "velocity", false},
    {"phi_rad", "euler", true},
    {"theta_rad", "euler", false},
    {"psi_rad", "euler", true},
    {"p_radps", "body_rates", false},
    {"q_radps", "body_rates", false},
    {"r_radps", "body_rates", false},
}};

}  // namespace fedsim::flight::nasa
