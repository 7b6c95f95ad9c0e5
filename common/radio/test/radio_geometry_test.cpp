// Radio path geometry against GeographicLib's geodesic directly, spherical-earth formulas and the
// published radio-horizon rules of thumb.
#include "common/radio/radio_geometry.hpp"

#include "common/radio/test/station_fixtures.hpp"

#include <gtest/gtest.h>

#include <cmath>

namespace fedsim::radio::test {
namespace {

TEST(RadioGeometry, RadioHorizonMatchesPublishedRules) {
  // Aviation rule: radio horizon [NM] = 1.23 sqrt(h [ft]) per antenna (4/3 earth); ITU's
  // d [km] = 4.12 sqrt(h [m]). Both are roundings of sqrt(2 k R h).
  for (const double h_ft : {100.0, 1000.0, 10000.0, 35000.0}) {
    const double d_m = radio_line_of_sight_m(0.0, h_ft * kFt);
    EXPECT_NEAR(d_m / kNm, 1.23 * std::sqrt(h_ft), 0.005 * d_m / kNm) << h_ft;
    EXPECT_NEAR(d_m / 1000.0, 4.12 * std::sqrt(h_ft * kFt), 0.005 * d_m / 1000.0) << h_ft;
  }
  // Two antennas add; below sea level counts as 0.
  EXPECT_NEAR(radio_line_of_sight_m(100.0, 400.0),
              radio_line_of_sight_m(0.0, 100.0) + radio_line_of_sight_m(400.0, 0.0), 1e-9);
  EXPECT_EQ(radio_line_of_sight_m(-10.0, -5.0), 0.0);
  EXPECT_TRUE(within_radio_line_of_sight(4.0, 3000.0, 100 * kNm));
  EXPECT_FALSE(within_radio_line_of_sight(4.0, 300.0, 100 * kNm));
}

TEST(RadioGeometry, DistanceAndAzimuthsAgreeWithGeodesic) {
  const GeoPoint station = sfo_vor_dme().position;
  for (double azimuth_deg = -180.0; azimuth_deg < 180.0; azimuth_deg += 45.0) {
    for (const double distance_m : {500.0, 20 * kNm, 120 * kNm}) {
      double forward_deg = 0.0;
      const GeoPoint aircraft = direct(station, azimuth_deg, distance_m, 0.0, &forward_deg);
      const LinkGeometry link = link_geometry(station, aircraft.lat_rad, aircraft.lon_rad, 3000.0);
      EXPECT_NEAR(link.ground_distance_m, distance_m, 1e-6);
      EXPECT_NEAR(wrap_pi(link.azimuth_from_station_true_rad - azimuth_deg * kDeg), 0.0,
                  1e-9);
      const Inverse back = inverse(aircraft, station);  // at the aircraft, towards the station
      EXPECT_NEAR(wrap_pi(link.azimuth_to_station_true_rad - back.azimuth1_deg * kDeg),
                  0.0, 1e-9);
      EXPECT_NEAR(wrap_pi(link.azimuth_to_station_true_rad -
                                     (forward_deg + 180.0) * kDeg),
                  0.0, 1e-9);
      EXPECT_NEAR(ground_distance_m(station, aircraft.lat_rad, aircraft.lon_rad), distance_m, 1e-6);
    }
  }
}

TEST(RadioGeometry, SlantRangeAndElevationAgreeWithSphericalEarth) {
  const GeoPoint station = sfo_vor_dme().position;
  const double radius_m = local_sphere_radius_m(station.lat_rad);
  for (const double distance_m : {1000.0, 10000.0, 60000.0}) {
    for (const double altitude_m : {300.0, 3000.0, 10000.0}) {
      const GeoPoint aircraft = direct(station, 60.0, distance_m, 0.0);
      const LinkGeometry link = link_geometry(station, aircraft.lat_rad, aircraft.lon_rad, altitude_m);
      const double r1 = radius_m + station.elevation_m;
      const double r2 = radius_m + altitude_m;
      const double angle = distance_m / radius_m;
      const double slant =
          spherical_slant_range_m(distance_m, station.elevation_m, altitude_m, radius_m);
      const double elevation = std::asin((r2 * std::cos(angle) - r1) / slant);
      EXPECT_NEAR(link.slant_range_m, slant, 2e-5 * slant) << distance_m << " " << altitude_m;
      EXPECT_NEAR(link.elevation_angle_rad, elevation, 1e-4) << distance_m << " " << altitude_m;
      EXPECT_NEAR(link.height_above_station_m, altitude_m - station.elevation_m, 1e-9);
    }
  }
  // Overhead: the slant range is the height above the antenna, the elevation 90 deg.
  const LinkGeometry overhead = link_geometry(station, station.lat_rad, station.lon_rad, 3000.0);
  EXPECT_NEAR(overhead.slant_range_m, 3000.0 - station.elevation_m, 1e-6);
  EXPECT_NEAR(overhead.elevation_angle_rad, units::kHalfPi, 1e-9);
}

TEST(RadioGeometry, AngleWrapping) {
  EXPECT_NEAR(wrap_two_pi(-0.5 * units::kPi), 1.5 * units::kPi, 1e-12);
  EXPECT_NEAR(wrap_two_pi(5 * units::kPi), units::kPi, 1e-12);
  EXPECT_EQ(wrap_two_pi(units::kTwoPi), 0.0);
  EXPECT_NEAR(wrap_pi(1.5 * units::kPi), -0.5 * units::kPi, 1e-12);
  EXPECT_NEAR(wrap_pi(-units::kPi), units::kPi, 1e-12);
}

}  // namespace
}  // namespace fedsim::radio::test
