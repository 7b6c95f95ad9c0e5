#include "flight/model/afcs/landing_figures.hpp"

#include <GeographicLib/LocalCartesian.hpp>

#include <cctype>
#include <cmath>
#include <cstdio>
#include <stdexcept>

namespace fedsim::flight::afcs {

namespace {

/// "28R" -> "10L": the reciprocal designator (numbers differ by 18, L and R swap, C stays).
std::string reciprocal_runway(const std::string& runway) {
  std::size_t digits = 0;
  while (digits < runway.size() && std::isdigit(static_cast<unsigned char>(runway[digits]))) ++digits;
  if (digits == 0) throw std::invalid_argument("runway '" + runway + "' has no number");
  int number = std::stoi(runway.substr(0, digits));
  number = number > 18 ? number - 18 : number + 18;
  std::string out = (number < 10 ? "0" : "") + std::to_string(number);
  const std::string side = runway.substr(digits);
  if (side == "L") out += "R";
  else if (side == "R") out += "L";
  else out += side;
  return out;
}

std::string format(const char* pattern, double a, double b) {
  char text[160];
  std::snprintf(text, sizeof text, pattern, a, b);
  return text;
}

}  // namespace

RunwayCentreline::RunwayCentreline(double threshold_lat_rad, double threshold_lon_rad, double far_lat_rad,
                                   double far_lon_rad)
    : lat0_deg_(threshold_lat_rad * units::kRadToDeg), lon0_deg_(threshold_lon_rad * units::kRadToDeg) {
  double east = 0.0, north = 0.0;
  plane_coordinates(far_lat_rad, far_lon_rad, east, north);
  length_m_ = std::hypot(east, north);
  if (!(length_m_ > 1.0)) throw std::invalid_argument("RunwayCentreline: the two ends coincide");
  along_east_ = east / length_m_;
  along_north_ = north / length_m_;
}

RunwayCentreline RunwayCentreline::from_table(const RunwayTable& table, const std::string& airport,
                                              const std::string& runway) {
  const RunwayEnd landing = table.at(airport, runway);
  const RunwayEnd far = table.at(airport, reciprocal_runway(runway));
  return RunwayCentreline(landing.threshold_lat_rad, landing.threshold_lon_rad, far.threshold_lat_rad,
                          far.threshold_lon_rad);
}

void RunwayCentreline::plane_coordinates(double lat_rad, double lon_rad, double& east_m, double& north_m) const {
  const GeographicLib::LocalCartesian plane(lat0_deg_, lon0_deg_, 0.0);
  double up = 0.0;
  plane.Forward(lat_rad * units::kRadToDeg, lon_rad * units::kRadToDeg, 0.0, east_m, north_m, up);
}

double RunwayCentreline::beyond_threshold_m(double lat_rad, double lon_rad) const {
  double e = 0.0, n = 0.0;
  plane_coordinates(lat_rad, lon_rad, e, n);
  return e * along_east_ + n * along_north_;
}

double RunwayCentreline::left_m(double lat_rad, double lon_rad) const {
  double e = 0.0, n = 0.0;
  plane_coordinates(lat_rad, lon_rad, e, n);
  // Left of the landing direction (east, north) = (along rotated by +90 deg counter-clockwise).
  return -e * along_north_ + n * along_east_;
}

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
