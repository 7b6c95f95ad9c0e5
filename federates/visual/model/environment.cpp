#include "visual/model/environment.hpp"

#include "common/units/units.hpp"
#include "common/util/input_checks.hpp"

#include <cmath>

namespace fedsim::visual {

void validate(const Environment& e, std::string_view where) {
  util::require_in_range(e.sun_elevation_rad, -units::kHalfPi, units::kHalfPi, where, "sun_elevation_rad",
                   "rad");
  util::require_in_range(e.sun_azimuth_rad, -units::kTwoPi, units::kTwoPi, where, "sun_azimuth_rad",
                   "rad");
  util::require_in_range(e.visibility_m, 10.0, 1.0e6, where, "visibility_m", "m");
  util::require_in_range(e.haze_top_agl_m, 10.0, 20000.0, where, "haze_top_agl_m", "m");
  if (e.cloud) {
    util::require_in_range(e.cloud->base_agl_m, 10.0, 20000.0, where, "cloud.base_agl_m", "m");
    util::require_in_range(e.cloud->top_agl_m, e.cloud->base_agl_m + 1.0, e.cloud->base_agl_m + 15000.0,
                     where, "cloud.top_agl_m", "m");
    util::require_in_range(e.cloud->visibility_in_cloud_m, 5.0, 5000.0, where,
                     "cloud.visibility_in_cloud_m", "m");
  }
}

double extinction_per_m(double visibility_m) {
  util::require_in_range(visibility_m, 1.0, 1.0e9, "extinction_per_m", "visibility_m", "m");
  return -std::log(0.05) / visibility_m;
}

}  // namespace fedsim::visual
