#include "common/hud/hud_inputs.hpp"

#include "common/symbology/input_checks.hpp"
#include "common/util/input_checks.hpp"

namespace fedsim::hud {

using symbology::check_angle;
using symbology::kMaxSpeedMps;
using symbology::kMaxVerticalMps;
using util::require_in_range;

void validate(const HudInputs& in, std::string_view where) {
  check_angle(in.pitch_rad, 90.0, where, "pitch_rad");
  check_angle(in.roll_rad, 180.0, where, "roll_rad");
  check_angle(in.heading_true_rad, 360.0, where, "heading_true_rad");
  check_angle(in.magnetic_variation_rad, 180.0, where, "magnetic_variation_rad");
  static constexpr const char* kVelocity[] = {"velocity_ned_mps[0]", "velocity_ned_mps[1]",
                                              "velocity_ned_mps[2]"};
  for (int i = 0; i < 3; ++i) {
    require_in_range(in.velocity_ned_mps[i], -1000.0, 1000.0, where, kVelocity[i], "m/s");
  }
  require_in_range(in.ias_mps, 0.0, kMaxSpeedMps, where, "ias_mps", "m/s");
  require_in_range(in.altitude_m, -1000.0, 20000.0, where, "altitude_m", "m");
  require_in_range(in.vertical_speed_mps, -kMaxVerticalMps, kMaxVerticalMps, where,
                   "vertical_speed_mps", "m/s");
  validate(in.flight_director, where);
}

}  // namespace fedsim::hud
