#include "visual/model/sun_position.hpp"

#include <cstdio>
#include <stdexcept>

#include "common/units/units.hpp"
#include "common/util/input_checks.hpp"

#include <algorithm>
#include <cmath>

namespace fedsim::visual {

namespace {

using units::kDegToRad;
using units::kRadToDeg;

// Julian day of a Gregorian calendar date and UTC time (Meeus eq. 7.1).
double julian_day(const UtcTime& t) {
  int y = t.year;
  int m = t.month;
  if (m <= 2) {
    y -= 1;
    m += 12;
  }
  const int a = y / 100;
  const int b = 2 - a + a / 4;
  return std::floor(365.25 * (y + 4716)) + std::floor(30.6001 * (m + 1)) + t.day + b - 1524.5 +
         t.seconds_of_day / 86400.0;
}

double wrap_degrees(double deg) {
  const double w = std::fmod(deg, 360.0);
  return w < 0.0 ? w + 360.0 : w;
}

// Refraction [deg] at apparent elevation e [deg] (NOAA's piecewise fit).
double refraction_deg(double e) {
  if (e > 85.0) return 0.0;
  const double te = std::tan(e * kDegToRad);
  double arcsec = 0.0;
  if (e > 5.0) {
    arcsec = 58.1 / te - 0.07 / (te * te * te) + 0.000086 / std::pow(te, 5);
  } else if (e > -0.575) {
    arcsec = 1735.0 + e * (-518.2 + e * (103.4 + e * (-12.79 + e * 0.711)));
  } else {
    arcsec = -20.772 / te;
  }
  return arcsec / 3600.0;
}

}  // namespace

SunDirection sun_direction(const UtcTime& time, double lat_rad, double lon_rad) {
  const std::string where = "sun_direction";
  util::require_in_range(time.year, 1800, 2200, where, "year");
  util::require_in_range(time.month, 1, 12, where, "month");
  util::require_in_range(time.day, 1, 31, where, "day");
  util::require_in_range(time.seconds_of_day, 0.0, 86400.0, where, "seconds_of_day", "s");
  util::require_in_range(lat_rad, -units::kHalfPi, units::kHalfPi, where, "lat_rad", "rad");
  util::require_in_range(lon_rad, -units::kPi, units::kPi, where, "lon_rad", "rad");

  const double t = (julian_day(time) - 2451545.0) / 36525.0;  // Julian centuries from J2000
  const double mean_longitude = wrap_degrees(280.46646 + t * (36000.76983 + t * 0.0003032));
  const double mean_anomaly = 357.52911 + t * (35999.05029 - 0.0001537 * t);
  const double eccentricity = 0.016708634 - t * (0.000042037 + 0.0000001267 * t);
  const double m = mean_anomaly * kDegToRad;
  const double centre = std::sin(m) * (1.914602 - t * (0.004817 + 0.000014 * t)) +
                        std::sin(2 * m) * (0.019993 - 0.000101 * t) + std::sin(3 * m) * 0.000289;
  const double true_longitude = mean_longitude + centre;
  const double omega = (125.04 - 1934.136 * t) * kDegToRad;
  const double apparent_longitude =
      (true_longitude - 0.00569 - 0.00478 * std::sin(omega)) * kDegToRad;
  const double mean_obliquity =
      23.0 + (26.0 + (21.448 - t * (46.815 + t * (0.00059 - t * 0.001813))) / 60.0) / 60.0;
  const double obliquity = (mean_obliquity + 0.00256 * std::cos(omega)) * kDegToRad;
  const double declination = std::asin(std::sin(obliquity) * std::sin(apparent_longitude));

  const double y = std::pow(std::tan(0.5 * obliquity), 2);
  const double l0 = mean_longitude * kDegToRad;
  const double equation_of_time_min =
      4.0 * kRadToDeg *
      (y * std::sin(2 * l0) - 2 * eccentricity * std::sin(m) +
       4 * eccentricity * y * std::sin(m) * std::cos(2 * l0) - 0.5 * y * y * std::sin(4 * l0) -
       1.25 * eccentricity * eccentricity * std::sin(2 * m));
  const double true_solar_time_min =
      wrap_degrees((time.seconds_of_day / 60.0 + equation_of_time_min + 4.0 * lon_rad * kRadToDeg) /
                   4.0) *
      4.0;
  const double hour_angle = (true_solar_time_min / 4.0 - 180.0) * kDegToRad;

  const double cos_zenith = std::sin(lat_rad) * std::sin(declination) +
                            std::cos(lat_rad) * std::cos(declination) * std::cos(hour_angle);
  const double geometric_elevation_deg =
      90.0 - std::acos(std::clamp(cos_zenith, -1.0, 1.0)) * kRadToDeg;
  // Azimuth from south, westward (Meeus eq. 13.5), turned to clockwise from north.
  const double azimuth_from_south =
      std::atan2(std::sin(hour_angle), std::cos(hour_angle) * std::sin(lat_rad) -
                                           std::tan(declination) * std::cos(lat_rad));
  SunDirection s;
  s.elevation_rad = (geometric_elevation_deg + refraction_deg(geometric_elevation_deg)) * kDegToRad;
  s.azimuth_rad = wrap_degrees((azimuth_from_south + units::kPi) * kRadToDeg) * kDegToRad;
  s.declination_rad = declination;
  return s;
}

}  // namespace fedsim::visual
