// The packs' stall-warning angles (the stick shaker's, flight/model/aircraft/stall_warning.hpp)
// from their own lift build-up: the angle of maximum lift and where CL reaches CL_max / 1.05^2.
#include "flight/model/aircraft/stall_warning.hpp"
#include "common/util/build_paths.hpp"

#include <gtest/gtest.h>

#include <cstdio>
#include <string>

namespace fedsim::flight {
namespace {

constexpr double kDeg = 3.14159265358979323846 / 180.0;

AircraftPack pack(const std::string& name) {
  return load_aircraft_pack(fedsim::util::data_dir() + "/aircraft/" + name);
}

TEST(StallWarning, TheC172WarnsBelowItsStallAngleAndFlapsRaiseItsMaximumLift) {
  const AircraftPack c172 = pack("c172.yaml");
  const StallAngles up = stall_angles(c172, 0.0);
  const StallAngles full = stall_angles(c172, 1.0);
  std::printf("C172 flaps up: CLmax %.3f at %.1f deg, warning %.1f deg; flaps full: CLmax %.3f at %.1f deg, warning %.1f deg\n",
              up.cl_max, up.alpha_cl_max_rad / kDeg, up.alpha_warning_rad / kDeg, full.cl_max,
              full.alpha_cl_max_rad / kDeg, full.alpha_warning_rad / kDeg);
  // The pack's build-up (JSBSim c172x): CLwbh peaks at 0.28 rad, but its CLalpha term (4.7 per
  // rad times alpha) keeps rising, so the pack's own maximum lies later, at 19.5 deg: the
  // shaker follows the aircraft fedsim flies.
  EXPECT_GT(up.alpha_cl_max_rad, 12.0 * kDeg);
  EXPECT_LT(up.alpha_cl_max_rad, 22.0 * kDeg);
  EXPECT_GT(up.cl_max, 1.0);
  EXPECT_LT(up.alpha_warning_rad, up.alpha_cl_max_rad);
  EXPECT_GT(up.alpha_warning_rad, up.alpha_cl_max_rad - 6.0 * kDeg);
  EXPECT_GT(full.cl_max, up.cl_max);  // flaps: more lift at the stall
  EXPECT_LE(full.alpha_warning_rad, up.alpha_warning_rad);  // and the warning comes no later
  // A wider margin warns earlier (negative control for the CL_max / k^2 search).
  EXPECT_LT(stall_angles(c172, 0.0, 1.2).alpha_warning_rad, up.alpha_warning_rad);
}

TEST(StallWarning, The737HasAWarningAngleAtEveryFlapSetting) {
  const AircraftPack b737 = pack("b737.yaml");
  for (double flaps : {0.0, 0.5, 1.0}) {
    const StallAngles s = stall_angles(b737, flaps);
    std::printf("737 flaps %.2f: CLmax %.3f at %.1f deg, warning %.1f deg\n", flaps, s.cl_max,
                s.alpha_cl_max_rad / kDeg, s.alpha_warning_rad / kDeg);
    EXPECT_GT(s.alpha_warning_rad, 5.0 * kDeg);
    EXPECT_LT(s.alpha_warning_rad, s.alpha_cl_max_rad);
  }
  EXPECT_THROW(stall_angles(b737, 1.5), std::invalid_argument);
  EXPECT_THROW(stall_angles(b737, 0.0, 0.9), std::invalid_argument);
}

}  // namespace
}  // namespace fedsim::flight
