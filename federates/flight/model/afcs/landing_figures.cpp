#include "flight/model/afcs/landing_figures.hpp"

#include <cmath>
#include <cstdio>
#include <stdexcept>

namespace fedsim::flight::afcs {

namespace {

std::string format(const char* pattern, double a, double b) {
  char text[160];
  std::snprintf(text, sizeof text, pattern, a, b);
  return text;
}

}  // namespace

LandingFigures landing_figures(const ClosedLoopFlight& flight, const RunwayCentreline& runway) {
  LandingFigures f;
  f.runway_length_m = runway.length_m();
  f.autopilot_engaged = flight.sample().fma.autopilot_engaged;
  f.alerts = flight.sample().fma.alerts;
  if (!flight.touchdown()) return f;
  f.touched_down = true;
  f.touchdown = *flight.touchdown();
  f.touchdown_left_of_centreline_m = runway.left_m(f.touchdown.lat_rad, f.touchdown.lon_rad);
  const GeodeticPosition end = flight.model().outputs().geodetic;
  f.stop_beyond_threshold_m = runway.beyond_threshold_m(end.lat_rad, end.lon_rad);
  f.stop_left_of_centreline_m = runway.left_m(end.lat_rad, end.lon_rad);
  f.stopped = flight.sample().main_gear_on_ground && flight.sample().ground_speed_mps < 0.5;
  f.max_rollout_offset_m = flight.max_rollout_offset_m();
  return f;
}

std::vector<std::string> limit_violations(const LandingFigures& f, const LandingLimits& l) {
  std::vector<std::string> out;
  constexpr double kFt = units::kFtToM;
  if (!f.touched_down) {
    out.push_back("no touchdown");
    return out;
  }
  const Touchdown& t = f.touchdown;
  if (std::abs(f.touchdown_left_of_centreline_m) > l.max_centreline_offset_m) {
    out.push_back(format("touchdown %.1f ft from the centreline > %.0f", std::abs(f.touchdown_left_of_centreline_m) / kFt,
                         l.max_centreline_offset_m / kFt));
  }
  if (t.sink_rate_mps > l.max_sink_rate_mps) {
    out.push_back(format("sink rate %.2f ft/s > %.1f", t.sink_rate_mps / kFt, l.max_sink_rate_mps / kFt));
  }
  if (t.beyond_threshold_m < l.min_beyond_threshold_m) {
    out.push_back(format("touchdown %.0f ft beyond the threshold < %.0f", t.beyond_threshold_m / kFt,
                         l.min_beyond_threshold_m / kFt));
  }
  if (t.beyond_threshold_m > l.max_beyond_threshold_m) {
    out.push_back(format("touchdown %.0f ft beyond the threshold > %.0f", t.beyond_threshold_m / kFt,
                         l.max_beyond_threshold_m / kFt));
  }
  if (std::abs(t.roll_rad) > l.max_bank_rad) {
    out.push_back(format("bank %.1f deg > %.0f", std::abs(t.roll_rad) * units::kRadToDeg, l.max_bank_rad * units::kRadToDeg));
  }
  if (!f.stopped) out.push_back("not stopped");
  if (f.stop_beyond_threshold_m > f.runway_length_m) {
    out.push_back(format("stopped %.0f m beyond the threshold, past the runway's %.0f m", f.stop_beyond_threshold_m,
                         f.runway_length_m));
  }
  if (std::abs(f.stop_left_of_centreline_m) > l.runway_half_width_m || f.max_rollout_offset_m > l.runway_half_width_m) {
    out.push_back(format("off the runway: %.1f m from the centreline (half width %.0f m)",
                         std::max(std::abs(f.stop_left_of_centreline_m), f.max_rollout_offset_m), l.runway_half_width_m));
  }
  return out;
}

}  // namespace fedsim::flight::afcs
