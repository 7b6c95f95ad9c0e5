#include "displays/model/display_inputs.hpp"

#include "common/symbology/input_checks.hpp"
#include "common/units/units.hpp"
#include "common/util/input_checks.hpp"

#include <cmath>
#include <string>

namespace fedsim::displays {

namespace {

using symbology::check_angle;
using symbology::kMaxSpeedMps;
using symbology::kMaxVerticalMps;
using util::reject;
using util::require_in_range;

constexpr double kMaxTrendMps = 100.0;     // a 10 s speed change beyond this is a bad input
constexpr double kMaxHeightChangeM = 2000.0;
constexpr std::size_t kIdentChars = 5;

void check_text(const std::string& text, std::size_t max_chars, std::string_view where,
                std::string_view field) {
  if (text.size() > max_chars) {
    reject(where, field,
           "'" + text + "' is longer than " + std::to_string(max_chars) + " characters");
  }
  for (char c : text) {
    if (c < 32 || c > 126) reject(where, field, "only printable ASCII characters are drawn");
  }
}

void check_optional(const std::optional<double>& v, double lo, double hi, std::string_view where,
                    std::string_view field, const char* unit) {
  if (v) require_in_range(*v, lo, hi, where, field, unit);
}

void check(const FlightModes& m, std::string_view where) {
  check_text(m.autothrottle_active, kFmaChars, where, "modes.autothrottle_active");
  check_text(m.autothrottle_armed, kFmaChars, where, "modes.autothrottle_armed");
  check_text(m.roll_active, kFmaChars, where, "modes.roll_active");
  check_text(m.roll_armed, kFmaChars, where, "modes.roll_armed");
  check_text(m.pitch_active, kFmaChars, where, "modes.pitch_active");
  check_text(m.pitch_armed, kFmaChars, where, "modes.pitch_armed");
  check_text(m.afds_status, kFmaChars, where, "modes.afds_status");
}

void check_pfd_air_data(const PfdInputs& in, std::string_view where) {
  require_in_range(in.ias_mps, 0.0, kMaxSpeedMps, where, "ias_mps", "m/s");
  require_in_range(in.ias_trend_mps, -kMaxTrendMps, kMaxTrendMps, where, "ias_trend_mps", "m/s");
  require_in_range(in.altitude_m, -1000.0, 20000.0, where, "altitude_m", "m");
  require_in_range(in.altitude_trend_m, -kMaxHeightChangeM, kMaxHeightChangeM, where,
                   "altitude_trend_m", "m");
  require_in_range(in.vertical_speed_mps, -kMaxVerticalMps, kMaxVerticalMps, where,
                   "vertical_speed_mps", "m/s");
  check_optional(in.baro_setting_pa, 80000.0, 110000.0, where, "baro_setting_pa", "Pa");
  check_optional(in.selected_speed_mps, 0.0, kMaxSpeedMps, where, "selected_speed_mps", "m/s");
  check_optional(in.selected_altitude_m, -1000.0, 20000.0, where, "selected_altitude_m", "m");
  check_optional(in.radio_altitude_m, -20.0, 10000.0, where, "radio_altitude_m", "m");
}

}  // namespace

void validate(const PfdInputs& in, std::string_view where) {
  check_angle(in.pitch_rad, 90.0, where, "pitch_rad");
  check_angle(in.roll_rad, 180.0, where, "roll_rad");
  require_in_range(in.lateral_specific_force_mps2, -50.0, 50.0, where,
                   "lateral_specific_force_mps2", "m/s^2");
  check_angle(in.heading_magnetic_rad, 360.0, where, "heading_magnetic_rad");
  check_angle(in.heading_true_rad, 360.0, where, "heading_true_rad");
  check_pfd_air_data(in, where);
  if (in.selected_heading_rad)
    check_angle(*in.selected_heading_rad, 360.0, where, "selected_heading_rad");
  require_in_range(in.localizer_deviation_dots, -10.0, 10.0, where, "localizer_deviation_dots",
                   "dots");
  require_in_range(in.glideslope_deviation_dots, -10.0, 10.0, where, "glideslope_deviation_dots",
                   "dots");
  validate(in.flight_director, where);
  check(in.modes, where);
}

namespace {

void check(const BearingPointer& p, std::string_view where, const char* bearing_field,
           const char* ident_field) {
  check_angle(p.relative_bearing_rad, 360.0, where, bearing_field);
  check_text(p.ident, kIdentChars, where, ident_field);
}

bool in_range(double v, double lo, double hi) { return std::isfinite(v) && v >= lo && v <= hi; }

// The field's name ("navaids[3].distance_m") is only built for a bad value: the checks run
// every frame and should not allocate.
void check_navaids(const std::vector<Navaid>& navaids, std::string_view where) {
  constexpr double kMaxBearing = units::kTwoPi, kMaxDistanceM = 2.0e7;  // 360 deg
  for (std::size_t i = 0; i < navaids.size(); ++i) {
    const Navaid& n = navaids[i];
    const auto name = [i](const char* field) {
      return "navaids[" + std::to_string(i) + "]." + field;
    };
    if (n.ident.size() > kIdentChars) check_text(n.ident, kIdentChars, where, name("ident"));
    if (!in_range(n.bearing_rad, -kMaxBearing, kMaxBearing)) {
      check_angle(n.bearing_rad, 360.0, where, name("bearing_rad"));
    }
    if (!in_range(n.distance_m, 0.0, kMaxDistanceM)) {
      require_in_range(n.distance_m, 0.0, kMaxDistanceM, where, name("distance_m"), "m");
    }
    for (char c : n.ident) {
      if (c < 32 || c > 126) check_text(n.ident, kIdentChars, where, name("ident"));
    }
  }
}

}  // namespace

void validate(const NdInputs& in, std::string_view where) {
  check_angle(in.heading_rad, 360.0, where, "heading_rad");
  check_angle(in.track_rad, 360.0, where, "track_rad");
  if (in.selected_heading_rad)
    check_angle(*in.selected_heading_rad, 360.0, where, "selected_heading_rad");
  check_angle(in.selected_course_rad, 360.0, where, "selected_course_rad");
  check_text(in.course_ident, kIdentChars, where, "course_ident");
  require_in_range(in.course_deviation_dots, -10.0, 10.0, where, "course_deviation_dots", "dots");
  require_in_range(in.dme_distance_m, 0.0, 1.0e6, where, "dme_distance_m", "m");
  check(in.bearing1, where, "bearing1.relative_bearing_rad", "bearing1.ident");
  check(in.bearing2, where, "bearing2.relative_bearing_rad", "bearing2.ident");
  check_navaids(in.navaids, where);
  require_in_range(in.range_nm, 5.0, 640.0, where, "range_nm", "NM");
  check_optional(in.ground_speed_mps, 0.0, 1000.0, where, "ground_speed_mps", "m/s");
  check_optional(in.true_airspeed_mps, 0.0, 1000.0, where, "true_airspeed_mps", "m/s");
}

}  // namespace fedsim::displays
