// The sun's position against independent facts: at local solar noon the elevation is
// 90 deg - latitude + declination; the declination is ~+23.44 deg at the June solstice and ~0 at
// the March equinox; the sun is in the south at noon north of the tropics, rises in the east,
// is below the horizon at midnight, moves 15 deg an hour.
#include "visual/model/sun_position.hpp"

#include "common/units/units.hpp"

#include <gtest/gtest.h>

#include <cmath>

namespace fedsim::visual {
namespace {

using units::kDegToRad;
using units::kRadToDeg;

TEST(SunPosition, NoonElevationAtSolsticeAndEquinox) {
  const double lat = 37.62 * kDegToRad, lon = -122.37 * kDegToRad;  // KSFO
  // 2024-06-20 20:51 UTC: the solstice; solar noon at KSFO is ~20:11 UTC.
  const SunDirection june = sun_direction({2024, 6, 20, (20 * 60 + 11) * 60.0}, lat, lon);
  EXPECT_NEAR(june.declination_rad * kRadToDeg, 23.44, 0.02);
  EXPECT_NEAR(june.elevation_rad * kRadToDeg, 90.0 - 37.62 + 23.44, 0.1);
  EXPECT_NEAR(june.azimuth_rad * kRadToDeg, 180.0, 2.0);
  // The March equinox, 2024-03-20 03:06 UTC; through it the declination grows at
  // 23.44 deg x 2 pi / 365.24 days = 0.403 deg a day: 0.289 deg at solar noon, 17.2 h later.
  const SunDirection march = sun_direction({2024, 3, 20, (20 * 60 + 17) * 60.0}, lat, lon);
  const double declination_deg = 0.403 * (17.0 + 11.0 / 60.0) / 24.0;
  EXPECT_NEAR(march.declination_rad * kRadToDeg, declination_deg, 0.02);
  EXPECT_NEAR(march.elevation_rad * kRadToDeg, 90.0 - 37.62 + declination_deg, 0.1);
}

TEST(SunPosition, RisesInTheEastAndIsDownAtMidnight) {
  const double lat = 37.62 * kDegToRad, lon = -122.37 * kDegToRad;
  // Equinox sunrise at KSFO ~14:10 UTC: the sun near the horizon, due east.
  const SunDirection rise = sun_direction({2024, 3, 20, (14 * 60 + 10) * 60.0}, lat, lon);
  EXPECT_NEAR(rise.elevation_rad * kRadToDeg, 0.0, 1.5);
  EXPECT_NEAR(rise.azimuth_rad * kRadToDeg, 90.0, 2.0);
  const SunDirection midnight = sun_direction({2024, 3, 20, 8 * 3600.0}, lat, lon);
  EXPECT_LT(midnight.elevation_rad * kRadToDeg, -40.0);
}

TEST(SunPosition, MovesFifteenDegreesAnHourOnTheEquatorAtTheEquinox) {
  // On the equator at the equinox the sun climbs the prime vertical: 1 h before solar noon
  // (~12:07 UTC at 0 E, the equation of time being about -7.5 min) it stands 75 deg high in
  // the east, 1 h after 75 deg high in the west.
  const SunDirection before = sun_direction({2024, 3, 20, (11 * 60 + 7.5) * 60.0}, 0.0, 0.0);
  EXPECT_NEAR(before.elevation_rad * kRadToDeg, 75.0, 0.3);
  EXPECT_NEAR(before.azimuth_rad * kRadToDeg, 90.0, 1.5);
  const SunDirection after = sun_direction({2024, 3, 20, (13 * 60 + 7.5) * 60.0}, 0.0, 0.0);
  EXPECT_NEAR(after.elevation_rad * kRadToDeg, 75.0, 0.3);
  EXPECT_NEAR(after.azimuth_rad * kRadToDeg, 270.0, 1.5);
}

TEST(SunPosition, RejectsBadInput) {
  EXPECT_THROW(sun_direction({2024, 13, 1, 0.0}, 0.0, 0.0), std::invalid_argument);
  EXPECT_THROW(sun_direction({2024, 1, 1, -1.0}, 0.0, 0.0), std::invalid_argument);
  EXPECT_THROW(sun_direction({2024, 1, 1, 0.0}, std::nan(""), 0.0), std::invalid_argument);
  EXPECT_THROW(sun_direction({2024, 1, 1, 0.0}, 0.0, 4.0), std::invalid_argument);
}

}  // namespace
}  // namespace fedsim::visual
