#include "common/radio/station_checks.hpp"

#include "common/units/units.hpp"

#include <cmath>
#include <functional>
#include <sstream>
#include <stdexcept>
#include <string>

namespace fedsim::radio {

namespace {

constexpr double kMaxElevationM = 9000.0;  // above Everest: a wrong unit, not a station
constexpr double kMinElevationM = -500.0;  // below the Dead Sea shore
constexpr double kMaxMarkerDistanceM = 20.0 * units::kNmToM;

// Names the record only when a check fails (the checks run every frame: no allocation then).
using Who = std::function<std::string()>;

void check_range(const Who& who, const std::string_view field, double value, double low,
                 double high, const char* range) {
  if (std::isfinite(value) && value >= low && value <= high) return;
  std::ostringstream text;
  text << who() << ": " << field << " = " << value << " (not finite or outside " << range << ")";
  throw std::invalid_argument(text.str());
}

void check_point(const Who& who, std::string_view name, const nav::GeoPoint& point) {
  const auto field = [&](const char* part) { return std::string(name) + part; };
  if (!std::isfinite(point.lat_rad) || std::abs(point.lat_rad) > units::kHalfPi) {
    check_range(who, field(".lat_rad"), point.lat_rad, -units::kHalfPi, units::kHalfPi,
                "[-pi/2, pi/2]");
  }
  if (!std::isfinite(point.lon_rad) || std::abs(point.lon_rad) > units::kPi) {
    check_range(who, field(".lon_rad"), point.lon_rad, -units::kPi, units::kPi, "[-pi, pi]");
  }
  if (!std::isfinite(point.elevation_m) || point.elevation_m < kMinElevationM ||
      point.elevation_m > kMaxElevationM) {
    check_range(who, field(".elevation_m"), point.elevation_m, kMinElevationM, kMaxElevationM,
                "[-500, 9000] m");
  }
}

void require(bool ok, const Who& who, const char* problem) {
  if (!ok) throw std::invalid_argument(who() + ": " + problem);
}

}  // namespace

void check_navaid(const nav::Navaid& navaid) {
  const Who who = [&navaid] {
    return "navaid '" + navaid.ident + "' (id " + std::to_string(navaid.id) + ")";
  };
  require(!navaid.ident.empty(), who, "empty ident");
  require(navaid.frequency_khz != 0, who, "frequency_khz = 0");
  check_point(who, "position", navaid.position);
  if (navaid.dme) check_point(who, "dme", *navaid.dme);
  check_range(who, "magnetic_variation_rad", navaid.magnetic_variation_rad, -units::kPi,
              units::kPi, "[-pi, pi]");
  check_range(who, "slaved_variation_rad", navaid.slaved_variation_rad, -units::kPi, units::kPi,
              "[-pi, pi]");
}

void check_approach(const nav::IlsApproach& approach) {
  const Who who = [&approach] {
    return "ILS '" + approach.ident + "' (" + approach.airport + " " + approach.runway + ")";
  };
  require(!approach.ident.empty(), who, "empty ident");
  require(approach.frequency_khz != 0, who, "frequency_khz = 0");
  check_range(who, "course_true_rad", approach.course_true_rad, -units::kTwoPi, units::kTwoPi,
              "[-2 pi, 2 pi]");
  check_range(who, "glide_path_angle_rad", approach.glide_path_angle_rad, 1.0 * units::kDegToRad,
              10.0 * units::kDegToRad, "[1, 10] deg");
  check_range(who, "threshold_crossing_height_m", approach.threshold_crossing_height_m, 0.0,
              100.0, "[0, 100] m");
  check_range(who, "course_width_rad", approach.course_width_rad, 0.0, 12.0 * units::kDegToRad,
              "[0, 12] deg");
  check_point(who, "threshold", approach.threshold);
  check_point(who, "localizer", approach.localizer);
  check_point(who, "glide_slope", approach.glide_slope);
  const auto check_marker = [&](const char* field, const std::optional<double>& distance_m) {
    if (distance_m) check_range(who, field, *distance_m, 0.0, kMaxMarkerDistanceM, "[0, 20] NM");
  };
  check_marker("outer_marker_distance_m", approach.outer_marker_distance_m);
  check_marker("middle_marker_distance_m", approach.middle_marker_distance_m);
  check_marker("inner_marker_distance_m", approach.inner_marker_distance_m);
}

bool has_vor(const nav::Navaid& navaid) {
  return navaid.type == nav::NavaidType::kVor || navaid.type == nav::NavaidType::kVorDme ||
         navaid.type == nav::NavaidType::kVortac;
}

bool has_ndb(const nav::Navaid& navaid) {
  return navaid.type == nav::NavaidType::kNdb || navaid.type == nav::NavaidType::kNdbDme;
}

}  // namespace fedsim::radio
