// Shared set-up of the closed-loop tests: the 737 pack, the KSFO 28R ILS record read from
// data/nav/ils.csv (threshold from data/nav/runways.csv) through common/navdb's row parser,
// configurations, and time-history helpers.
#pragma once

#include "common/units/units.hpp"
#include "common/util/build_paths.hpp"
#include "flight/model/afcs/closed_loop_flight.hpp"
#include "flight/model/afcs/ils_approach_source.hpp"
#include "flight/model/afcs/lateral_guidance.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <functional>
#include <memory>
#include <string>
#include <vector>

namespace fedsim::flight::afcs::testing {

inline constexpr double kDeg = units::kDegToRad;
inline constexpr double kFt = units::kFtToM;
inline constexpr double kKt = units::kKtToMps;
inline constexpr double kNm = units::kNmToM;
inline constexpr double kFpm = units::kFpmToMps;

/// KSFO 28R (I-GWQ 111.70 MHz) as data/nav/ils.csv and runways.csv give it, with its course laid
/// through the threshold: the table's true course (297.903 deg, from X-Plane's earth_nav.dat)
/// passes 7.6 m from the threshold, while the antenna lies on the runway's centreline (0.03 m)
/// and the runway's azimuth is 297.814 deg; a localizer is aligned with the centreline (ICAO
/// Annex 10 Vol I 3.1.3.6.1, Cat III: 3 m at the threshold). See ilsApproach test below.
inline const nav::IlsApproach& ksfo_28r_as_published() {
  static const nav::IlsApproach ils = load_default_ils_approach("KSFO", "28R");
  return ils;
}
inline const nav::IlsApproach& ksfo_28r() {
  static const nav::IlsApproach ils = with_course_through_threshold(ksfo_28r_as_published());
  return ils;
}

inline AircraftPack b737_pack() {
  return load_aircraft_pack(fedsim::util::data_dir() + "/aircraft/b737.yaml");
}

/// Landing configuration: flaps 30 (0.875 of the 737's 40 deg travel), gear down.
inline AircraftControls landing_configuration() {
  AircraftControls c;
  c.flaps = 0.875;
  c.gear_down = true;
  return c;
}
/// Clean configuration: flaps and gear up.
inline AircraftControls clean_configuration() {
  AircraftControls c;
  c.flaps = 0.0;
  c.gear_down = false;
  return c;
}

inline std::unique_ptr<ClosedLoopFlight> make_flight(ClosedLoopOptions options = {}) {
  return std::make_unique<ClosedLoopFlight>(b737_pack(), ksfo_28r(), options);
}

inline McpButtons cmd() { McpButtons b; b.autopilot_engage = true; return b; }
inline McpButtons button(bool McpButtons::*which) { McpButtons b; b.*which = true; return b; }

/// Writes the history as CSV when FEDSIM_AFCS_TRACE_DIR is set (for plots while tuning).
inline void maybe_trace(const ClosedLoopFlight& f, const std::string& name) {
  const char* dir = std::getenv("FEDSIM_AFCS_TRACE_DIR");
  if (dir == nullptr) return;
  std::ofstream out(std::string(dir) + "/" + name + ".csv");
  out << "t,before_thr_m,left_m,gear_h_m,alt_m,cas_kt,gs_kt,vs_fpm,pitch_deg,roll_deg,hdg_deg,trk_deg,"
         "beta_deg,r_dps,bank_c_deg,pitch_c_deg,path_c_deg,loc_dev,gs_dev,elev,ail,rud,thr,trim,steer,brake,wow,nose,lat,vert,thrust\n";
  for (const FlightSample& s : f.history()) {
    out << s.time_s << ',' << s.before_threshold_m << ',' << s.left_of_course_m << ',' << s.gear_height_m << ','
        << s.altitude_m << ',' << s.cas_mps / kKt << ',' << s.ground_speed_mps / kKt << ','
        << s.vertical_speed_mps / kFpm << ',' << s.pitch_rad / kDeg << ',' << s.roll_rad / kDeg << ','
        << s.heading_rad / kDeg << ',' << s.track_rad / kDeg << ',' << s.sideslip_rad / kDeg << ',' << s.yaw_rate_radps / kDeg << ',' << s.bank_command_rad / kDeg << ',' << s.pitch_command_rad / kDeg << ',' << s.path_command_rad / kDeg << ',' << s.localizer_deviation << ','
        << s.glide_slope_deviation << ',' << s.elevator << ',' << s.aileron << ',' << s.rudder << ','
        << s.throttle << ',' << s.pitch_trim << ',' << s.steering << ',' << s.brake << ','
        << s.main_gear_on_ground << ',' << s.nose_gear_on_ground << ',' << to_string(s.fma.lateral) << ','
        << to_string(s.fma.vertical) << ',' << to_string(s.fma.thrust) << '\n';
  }
}

/// The largest value of f over the samples from time t0 on.
template <class F>
double max_over(const std::vector<FlightSample>& h, double t0, F f) {
  double m = -INFINITY;
  for (const FlightSample& s : h) if (s.time_s >= t0) m = std::max(m, f(s));
  return m;
}
template <class F>
double min_over(const std::vector<FlightSample>& h, double t0, F f) {
  double m = INFINITY;
  for (const FlightSample& s : h) if (s.time_s >= t0) m = std::min(m, f(s));
  return m;
}

/// Full scale of the ILS deviations (150 uA) is 2 dots on the 737's attitude indicator.
inline constexpr double kDotsPerFullScale = 2.0;

/// Started trimmed at the point with the AFCS engaged: CMD, A/T ARM then SPEED at the
/// trimmed CAS, ALT HLD (holding the present altitude).
inline void engage_holding(ClosedLoopFlight& f) {
  f.mcp().autothrottle_armed = true;
  f.press(cmd());
  f.step();
  f.press(button(&McpButtons::altitude_hold));
  f.press(button(&McpButtons::speed));
  f.step();
}

/// Prints the mode transitions (with FEDSIM_AFCS_TRACE_DIR set).
inline void maybe_print_transitions(const ClosedLoopFlight& f) {
  if (std::getenv("FEDSIM_AFCS_TRACE_DIR") == nullptr) return;
  for (const ModeTransition& t : f.transitions()) {
    std::printf("  %7.2f s %-15s %-9s -> %-9s (%s)\n", t.time_s, std::string(to_string(t.channel)).c_str(),
                std::string(t.from).c_str(), std::string(t.to).c_str(), std::string(t.reason).c_str());
  }
}

/// The first time the lateral or vertical mode became `mode` (NaN if never).
inline double time_entered(const std::vector<ModeTransition>& transitions, ModeTransition::Channel channel,
                           std::string_view mode) {
  for (const ModeTransition& t : transitions) if (t.channel == channel && t.to == mode) return t.time_s;
  return NAN;
}

}  // namespace fedsim::flight::afcs::testing
