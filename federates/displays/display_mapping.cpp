#include "displays/display_mapping.hpp"

#include "common/units/units.hpp"

#include <algorithm>
#include <cmath>

namespace fedsim::displays {
namespace {

using symbology_mapping::DisplayContext;
using symbology_mapping::flight_director;
using symbology_mapping::wrap_2pi;

constexpr double kScaleDots = 2.0;      // full-scale deflection, dots each side
constexpr double kPegDots = 2.5;        // the pointer stops at the scale's end
constexpr double kIasTrendS = 10.0;     // Boeing speed trend: the speed in 10 s
constexpr double kAltitudeTrendS = 6.0; // altitude trend: in 6 s
constexpr double kStandardPressurePa = 101325.0;
// The model's own limits (model/display_inputs.cpp): a trend beyond them is drawn at the limit.
constexpr double kMaxTrendMps = 100.0;
constexpr double kMaxHeightChangeM = 2000.0;

bool tuned(const msg::NavReceiver& nav) {
  return nav.status() != msg::SIGNAL_NOT_TUNED && nav.status() != msg::SIGNAL_NO_STATION;
}

NavSignal valid_or_failed(msg::SignalStatus status) {
  return status == msg::SIGNAL_VALID ? NavSignal::kValid : NavSignal::kFailed;
}

bool usable_vor(const msg::NavReceiver& nav) {
  return nav.signal() == msg::NAV_SIGNAL_VOR && nav.status() == msg::SIGNAL_VALID;
}

BearingPointer vor_pointer(const msg::NavReceiver& nav, double heading_true_rad) {
  BearingPointer p;
  p.source = BearingSource::kVor;
  p.valid = usable_vor(nav);
  p.ident = nav.ident().to_string().substr(0, 5);
  if (p.valid) p.relative_bearing_rad = wrap_2pi(nav.bearing_to_station_true_rad() - heading_true_rad);
  return p;
}

NavaidKind kind_of(nav::NavaidType type) {
  switch (type) {
    case nav::NavaidType::kVor: return NavaidKind::kVor;
    case nav::NavaidType::kVorDme:
    case nav::NavaidType::kVortac: return NavaidKind::kVorDme;
    case nav::NavaidType::kDme:
    case nav::NavaidType::kTacan: return NavaidKind::kDme;
    case nav::NavaidType::kNdb:
    case nav::NavaidType::kNdbDme: return NavaidKind::kNdb;
  }
  return NavaidKind::kVor;
}

}  // namespace

NearbyNavaids nearby_navaids(const nav::NavDatabase& db, double lat_rad, double lon_rad, double range_nm,
                             std::size_t limit) {
  NearbyNavaids out;
  const std::vector<nav::NavaidHit> hits = db.within(lat_rad, lon_rad, range_nm * units::kNmToM);
  if (hits.empty()) return out;
  out.magnetic_variation_rad = symbology_mapping::magnetic_variation_of_nearest(hits);
  for (const nav::NavaidHit& hit : hits) {
    if (out.navaids.size() >= limit) break;
    Navaid n;
    n.ident = hit.navaid.ident.substr(0, 5);
    n.kind = kind_of(hit.navaid.type);
    n.bearing_rad = std::fmod(hit.bearing_true_rad - out.magnetic_variation_rad + 2.0 * units::kTwoPi, units::kTwoPi);
    n.distance_m = hit.distance_m;
    out.navaids.push_back(std::move(n));
  }
  return out;
}

double deviation_dots(double full_scale_fraction) {
  if (!std::isfinite(full_scale_fraction)) return 0.0;
  return std::clamp(kScaleDots * full_scale_fraction, -kPegDots, kPegDots);
}

bool is_localizer_frequency(std::uint32_t frequency_khz) {
  if (frequency_khz < 108000 || frequency_khz > 111975) return false;
  return (frequency_khz / 100) % 2 == 1;  // 108.10, 108.15, 108.30, ...
}

NavSignal localizer_signal(const msg::NavReceiver& nav) {
  if (nav.signal() == msg::NAV_SIGNAL_LOCALIZER) return valid_or_failed(nav.status());
  if (nav.signal() == msg::NAV_SIGNAL_VOR) return NavSignal::kNotTuned;
  // No course signal: a localizer channel that is tuned (a station on it, failed or out of
  // coverage, or the receiver failed) is flagged; a frequency with no localizer is not.
  if (is_localizer_frequency(nav.frequency_khz()) && tuned(nav)) return NavSignal::kFailed;
  return NavSignal::kNotTuned;
}

NavSignal glideslope_signal(const msg::NavReceiver& nav) {
  const NavSignal loc = localizer_signal(nav);
  if (loc == NavSignal::kNotTuned) return NavSignal::kNotTuned;
  if (loc == NavSignal::kFailed) return NavSignal::kFailed;
  return valid_or_failed(nav.glideslope_status());
}

NavSignal course_signal(const msg::NavReceiver& nav) {
  if (nav.signal() != msg::NAV_SIGNAL_NONE) return valid_or_failed(nav.status());
  return tuned(nav) ? NavSignal::kFailed : NavSignal::kNotTuned;
}

MarkerBeacon marker_of(msg::MarkerBeaconKind kind) {
  switch (kind) {
    case msg::MARKER_OUTER: return MarkerBeacon::kOuter;
    case msg::MARKER_MIDDLE: return MarkerBeacon::kMiddle;
    case msg::MARKER_INNER: return MarkerBeacon::kInner;
    default: return MarkerBeacon::kNone;
  }
}

ToFrom to_from_of(msg::ToFromFlag flag) {
  switch (flag) {
    case msg::TO_FROM_TO: return ToFrom::kTo;
    case msg::TO_FROM_FROM: return ToFrom::kFrom;
    default: return ToFrom::kOff;
  }
}

FlightModes flight_modes(const msg::FlightModeAnnunciator& fma) {
  FlightModes m;
  switch (fma.thrust()) {
    case msg::FMA_THRUST_ARM: m.autothrottle_active = "ARM"; break;
    case msg::FMA_THRUST_SPEED: m.autothrottle_active = "MCP SPD"; break;
    case msg::FMA_THRUST_CLIMB: m.autothrottle_active = "N1"; break;
    case msg::FMA_THRUST_IDLE: m.autothrottle_active = "THR HLD"; break;
    case msg::FMA_THRUST_RETARD: m.autothrottle_active = "RETARD"; break;
    case msg::FMA_THRUST_GO_AROUND: m.autothrottle_active = "GA"; break;
    default: break;
  }
  switch (fma.roll()) {
    case msg::FMA_ROLL_CWS: m.roll_active = "CWS R"; break;
    case msg::FMA_ROLL_WING_LEVEL: m.roll_active = "WLV"; break;
    case msg::FMA_ROLL_HEADING_HOLD: m.roll_active = "HDG HOLD"; break;
    case msg::FMA_ROLL_HEADING_SELECT: m.roll_active = "HDG SEL"; break;
    case msg::FMA_ROLL_LOCALIZER: m.roll_active = "VOR/LOC"; break;
    case msg::FMA_ROLL_ALIGN: m.roll_active = "ALIGN"; break;
    case msg::FMA_ROLL_ROLLOUT: m.roll_active = "ROLLOUT"; break;
    case msg::FMA_ROLL_GO_AROUND: m.roll_active = "TOGA"; break;
    default: break;
  }
  if (fma.roll_armed_localizer()) m.roll_armed = "VOR/LOC";
  else if (fma.roll_armed_rollout()) m.roll_armed = "ROLLOUT";
  switch (fma.pitch()) {
    case msg::FMA_PITCH_CWS: m.pitch_active = "CWS P"; break;
    case msg::FMA_PITCH_ALTITUDE_HOLD: m.pitch_active = "ALT HOLD"; break;
    case msg::FMA_PITCH_ALTITUDE_CAPTURE: m.pitch_active = "ALT ACQ"; break;
    case msg::FMA_PITCH_VERTICAL_SPEED: m.pitch_active = "V/S"; break;
    case msg::FMA_PITCH_LEVEL_CHANGE: m.pitch_active = "MCP SPD"; break;
    case msg::FMA_PITCH_GLIDE_SLOPE: m.pitch_active = "G/S"; break;
    case msg::FMA_PITCH_FLARE: m.pitch_active = "FLARE"; break;
    case msg::FMA_PITCH_ROLLOUT: m.pitch_active = "ROLLOUT"; break;
    case msg::FMA_PITCH_GO_AROUND: m.pitch_active = "TOGA"; break;
    default: break;
  }
  if (fma.pitch_armed_glide_slope()) m.pitch_armed = "G/S";
  else if (fma.pitch_armed_altitude()) m.pitch_armed = "ALT ACQ";
  else if (fma.pitch_armed_flare()) m.pitch_armed = "FLARE";
  m.afds_status = fma.autopilot_engaged() ? "CMD" : fma.flight_director_on() ? "FD" : "";
  return m;
}

PfdInputs pfd_inputs(const msg::AircraftState& s, const msg::NavigationState* nav,
                     const msg::AutopilotState* autopilot, const DisplayContext& context) {
  PfdInputs in;
  in.pitch_rad = s.theta_rad();
  in.roll_rad = s.phi_rad();
  in.lateral_specific_force_mps2 = s.specific_force_eye_body_mps2()[1];
  in.heading_true_rad = wrap_2pi(s.psi_rad());
  in.heading_magnetic_rad = wrap_2pi(s.psi_rad() - context.magnetic_variation_rad);
  in.ias_mps = std::max(0.0, s.air().cas_mps());
  // dV/dt along the path ~ u_dot; as calibrated airspeed, scaled by CAS/TAS.
  const double cas_per_tas = s.air().tas_mps() > 1.0 ? s.air().cas_mps() / s.air().tas_mps() : 1.0;
  in.ias_trend_mps = std::clamp(kIasTrendS * s.velocity_body_dot_mps2()[0] * cas_per_tas, -kMaxTrendMps, kMaxTrendMps);
  in.altitude_m = s.altitude_msl_m();
  in.vertical_speed_mps = s.climb_rate_mps();
  in.altitude_trend_m = std::clamp(kAltitudeTrendS * s.climb_rate_mps(), -kMaxHeightChangeM, kMaxHeightChangeM);
  in.baro_setting_pa = kStandardPressurePa;
  in.radio_altitude_m = std::max(0.0, s.height_agl_m());
  if (nav != nullptr) {
    const msg::NavReceiver& nav1 = nav->nav()[0];
    in.localizer = localizer_signal(nav1);
    in.glideslope = glideslope_signal(nav1);
    if (in.localizer == NavSignal::kValid) in.localizer_deviation_dots = deviation_dots(nav1.course_deviation());
    if (in.glideslope == NavSignal::kValid) in.glideslope_deviation_dots = deviation_dots(nav1.glideslope_deviation());
    in.marker = marker_of(nav->marker().beacon());
  }
  in.flight_director = flight_director(nav, autopilot);
  if (autopilot != nullptr) {
    in.modes = flight_modes(autopilot->fma());
    if (autopilot->fma().pitch() == msg::FMA_PITCH_ALTITUDE_HOLD && std::isfinite(autopilot->hold_altitude_msl_m())) {
      in.selected_altitude_m = std::clamp(autopilot->hold_altitude_msl_m(), -1000.0, 20000.0);
    }
  }
  return in;
}

NdInputs nd_inputs(const msg::AircraftState& s, const msg::NavigationState* nav, const DisplayContext& context,
                   std::vector<Navaid> navaids, double range_nm) {
  NdInputs in;
  in.heading_rad = wrap_2pi(s.psi_rad() - context.magnetic_variation_rad);
  const double vn = s.velocity_ned_mps()[0], ve = s.velocity_ned_mps()[1];
  // Below 1 m/s over the ground the track is the heading (a track of noise is no track).
  in.track_rad = std::hypot(vn, ve) > 1.0 ? wrap_2pi(std::atan2(ve, vn) - context.magnetic_variation_rad) : in.heading_rad;
  in.ground_speed_mps = std::max(0.0, s.ground_speed_mps());
  in.true_airspeed_mps = std::max(0.0, s.air().tas_mps());
  in.range_nm = range_nm;
  in.navaids = std::move(navaids);
  if (nav != nullptr) {
    const msg::NavReceiver& nav1 = nav->nav()[0];
    in.course = course_signal(nav1);
    in.course_is_localizer = nav1.signal() == msg::NAV_SIGNAL_LOCALIZER || is_localizer_frequency(nav1.frequency_khz());
    in.course_ident = nav1.ident().to_string().substr(0, 5);
    // A localizer's course is its front course (magnetic); a VOR's the OBS.
    in.selected_course_rad = in.course_is_localizer && in.course == NavSignal::kValid
                                 ? wrap_2pi(nav1.course_true_rad() - context.magnetic_variation_rad)
                                 : wrap_2pi(nav1.obs_course_magnetic_rad());
    if (in.course == NavSignal::kValid) in.course_deviation_dots = deviation_dots(nav1.course_deviation());
    in.to_from = in.course == NavSignal::kValid && !in.course_is_localizer ? to_from_of(nav1.to_from()) : ToFrom::kOff;
    in.dme_valid = nav1.dme_status() == msg::SIGNAL_VALID && std::isfinite(nav1.dme_slant_range_m()) &&
                   nav1.dme_slant_range_m() >= 0.0;
    if (in.dme_valid) in.dme_distance_m = std::min(nav1.dme_slant_range_m(), 2.0e7);
    const msg::NavReceiver& nav2 = nav->nav()[1];
    in.bearing1 = vor_pointer(usable_vor(nav2) || !usable_vor(nav1) ? nav2 : nav1, s.psi_rad());
    const msg::AdfReceiverState& adf = nav->adf();
    in.bearing2.source = BearingSource::kAdf;
    in.bearing2.valid = adf.status() == msg::SIGNAL_VALID && std::isfinite(adf.relative_bearing_rad());
    in.bearing2.ident = adf.ident().to_string().substr(0, 5);
    if (in.bearing2.valid) in.bearing2.relative_bearing_rad = wrap_2pi(adf.relative_bearing_rad());
  }
  return in;
}

std::string aircraft_state_problem(const msg::AircraftState& s) {
  struct Field {
    const char* name;
    double value, lo, hi;
  };
  const Field fields[] = {
      {"theta_rad", s.theta_rad(), -units::kHalfPi, units::kHalfPi},
      {"phi_rad", s.phi_rad(), -units::kPi, units::kPi},
      {"psi_rad", s.psi_rad(), -4.0 * units::kPi, 4.0 * units::kPi},
      {"altitude_msl_m", s.altitude_msl_m(), -1000.0, 20000.0},
      {"height_agl_m", s.height_agl_m(), -1000.0, 30000.0},
      {"climb_rate_mps", s.climb_rate_mps(), -150.0, 150.0},
      {"ground_speed_mps", s.ground_speed_mps(), 0.0, 2000.0},
      {"air.cas_mps", s.air().cas_mps(), -1.0, 400.0},
      {"air.tas_mps", s.air().tas_mps(), -1.0, 2000.0},
      {"velocity_ned_mps[0]", s.velocity_ned_mps()[0], -2000.0, 2000.0},
      {"velocity_ned_mps[1]", s.velocity_ned_mps()[1], -2000.0, 2000.0},
      {"velocity_ned_mps[2]", s.velocity_ned_mps()[2], -2000.0, 2000.0},
      {"velocity_body_dot_mps2[0]", s.velocity_body_dot_mps2()[0], -1000.0, 1000.0},
      {"specific_force_eye_body_mps2[1]", s.specific_force_eye_body_mps2()[1], -50.0, 50.0},
  };
  for (const Field& f : fields) {
    if (!std::isfinite(f.value)) return std::string("field '") + f.name + "': not a finite number";
    if (f.value < f.lo || f.value > f.hi) {
      return std::string("field '") + f.name + "': " + std::to_string(f.value) + " outside [" + std::to_string(f.lo) +
             ", " + std::to_string(f.hi) + "]";
    }
  }
  return "";
}

}  // namespace fedsim::displays
