// Names of the aerodynamic axes, as written in aircraft packs.
#include "flight/model/aircraft/pack_aerodynamics.hpp"

namespace fedsim::flight {

std::string_view aero_axis_name(AeroAxis axis) {
  static constexpr std::array<std::string_view, kAeroAxisCount> kNames = {
      "lift", "drag", "side_force", "roll_moment", "pitch_moment", "yaw_moment"};
  return kNames.at(static_cast<std::size_t>(axis));
}

}  // namespace fedsim::flight
