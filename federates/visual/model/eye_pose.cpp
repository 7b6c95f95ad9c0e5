#include "visual/model/eye_pose.hpp"

#include "common/units/units.hpp"
#include "common/util/input_checks.hpp"

namespace fedsim::visual {

using units::kHalfPi;
using units::kPi;
using units::kTwoPi;

void validate(const EyePose& p, std::string_view where) {
  util::require_in_range(p.lat_rad, -kHalfPi, kHalfPi, where, "lat_rad", "rad");
  util::require_in_range(p.lon_rad, -kPi, kPi, where, "lon_rad", "rad");
  util::require_in_range(p.alt_msl_m, -1000.0, 100000.0, where, "alt_msl_m", "m");
  util::require_in_range(p.phi_rad, -kPi, kPi, where, "phi_rad", "rad");
  util::require_in_range(p.theta_rad, -kHalfPi, kHalfPi, where, "theta_rad", "rad");
  util::require_in_range(p.psi_rad, -kTwoPi, kTwoPi, where, "psi_rad", "rad");
}

}  // namespace fedsim::visual
