// The sun's direction seen from a place at a UTC date and time: the NOAA solar calculator's
// equations (after Meeus, Astronomical Algorithms, 1991, chapters 24-25; accurate to ~0.01 deg
// for 1800-2100), plus the standard atmospheric refraction near the horizon (Saemundsson/Bennett
// form, NOAA). The instructor's time of day enters the visual system through this.
#pragma once

#include "common/instructor/utc_time.hpp"

namespace fedsim::visual {

using instructor::UtcTime;
using instructor::parse_utc;

struct SunDirection {
  double elevation_rad = 0.0;  // apparent elevation (refraction included) [rad]
  double azimuth_rad = 0.0;    // true, clockwise from north, [0, 2 pi) [rad]
  double declination_rad = 0.0;
};

/// Throws std::invalid_argument naming the field for a date outside 1800-2200, a bad month or
/// day, seconds outside [0, 86400], latitude outside +-90 deg or longitude outside +-180 deg.
SunDirection sun_direction(const UtcTime& time, double lat_rad, double lon_rad);

}  // namespace fedsim::visual
