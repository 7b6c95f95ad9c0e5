#include "nav/nav_component.hpp"
#include "common/util/cli_checks.hpp"

#include "common/radio/approach_geometry.hpp"
#include "common/units/units.hpp"

#include <cmath>
#include <limits>
#include <stdexcept>

namespace fedsim::nav {

namespace {

msg::SignalStatus to_message(radio::SignalStatus s) {
  switch (s) {
    case radio::SignalStatus::kValid: return msg::SIGNAL_VALID;
    case radio::SignalStatus::kInvalidInput: return msg::SIGNAL_INVALID_INPUT;
    case radio::SignalStatus::kNotTuned: return msg::SIGNAL_NOT_TUNED;
    case radio::SignalStatus::kNoStation: return msg::SIGNAL_NO_STATION;
    case radio::SignalStatus::kReceiverFailed: return msg::SIGNAL_RECEIVER_FAILED;
    case radio::SignalStatus::kStationOffAir: return msg::SIGNAL_STATION_OFF_AIR;
    case radio::SignalStatus::kOutOfServiceVolume: return msg::SIGNAL_OUT_OF_SERVICE_VOLUME;
    case radio::SignalStatus::kBelowRadioHorizon: return msg::SIGNAL_BELOW_RADIO_HORIZON;
    case radio::SignalStatus::kConeOfConfusion: return msg::SIGNAL_CONE_OF_CONFUSION;
    case radio::SignalStatus::kOutsideCoverage: return msg::SIGNAL_OUTSIDE_COVERAGE;
    case radio::SignalStatus::kBehindAntenna: return msg::SIGNAL_BEHIND_ANTENNA;
  }
  return msg::SIGNAL_INVALID_INPUT;
}

msg::ToFromFlag to_message(radio::ToFrom f) {
  return f == radio::ToFrom::kTo ? msg::TO_FROM_TO : f == radio::ToFrom::kFrom ? msg::TO_FROM_FROM : msg::TO_FROM_OFF;
}

msg::MarkerBeaconKind to_message(MarkerBeacon b) {
  switch (b) {
    case MarkerBeacon::kOuter: return msg::MARKER_OUTER;
    case MarkerBeacon::kMiddle: return msg::MARKER_MIDDLE;
    case MarkerBeacon::kInner: return msg::MARKER_INNER;
    case MarkerBeacon::kNone: break;
  }
  return msg::MARKER_NONE;
}

std::string bounded(std::string_view s) { return std::string(s.substr(0, 8)); }

// What an autopilot needs to turn the deviations into distances (0 when not valid): the
// localizer's full-scale angle, the distances from both antennas and, along the course, to the
// threshold (the distance from the antenna projected on the course line, less the antenna's
// distance to the threshold).
void fill_ils_geometry(const radio::NavReading& r, msg::NavReceiver& out) {
  const bool localizer = r.valid() && r.signal == radio::NavSignal::kLocalizer && r.approach != nullptr;
  const radio::LocalizerReading& loc = r.localizer;
  out.localizer_half_width_rad(localizer ? loc.course_half_width_rad : 0.0);
  out.localizer_distance_m(localizer ? loc.distance_from_antenna_m : 0.0);
  out.threshold_distance_m(localizer ? loc.distance_from_antenna_m * std::cos(loc.angle_off_course_rad) -
                                           radio::approach_geometry(*r.approach).threshold_along_m
                                     : 0.0);
  out.glideslope_distance_m(localizer && r.glide_slope.valid() ? r.glide_slope.distance_from_antenna_m : 0.0);
}

void fill_receiver(const radio::NavReading& r, const radio::NavTuning& tuning, msg::NavReceiver& out) {
  out.frequency_khz(tuning.frequency_khz);
  out.obs_course_magnetic_rad(tuning.obs_course_magnetic_rad);
  out.signal(r.signal == radio::NavSignal::kVor         ? msg::NAV_SIGNAL_VOR
             : r.signal == radio::NavSignal::kLocalizer ? msg::NAV_SIGNAL_LOCALIZER
                                                 : msg::NAV_SIGNAL_NONE);
  out.status(to_message(r.status));
  out.ident(bounded(r.ident()));
  const bool vor = r.valid() && r.signal == radio::NavSignal::kVor;
  out.radial_magnetic_rad(vor ? r.vor.radial_magnetic_rad : 0.0);
  out.bearing_to_station_true_rad(r.bearing_to_station_true_rad());
  out.course_true_rad(r.course_true_rad());
  out.course_deviation(r.course_deviation());
  out.to_from(vor ? to_message(r.vor.to_from) : msg::TO_FROM_OFF);
  out.glideslope_status(to_message(r.glide_slope.status));
  out.glideslope_deviation(r.glide_slope.valid() ? r.glide_slope.deviation : 0.0);
  out.glide_path_angle_rad(r.glide_slope.valid() ? r.glide_slope.glide_path_angle_rad : 0.0);
  fill_ils_geometry(r, out);
  out.dme_status(to_message(r.dme.status));
  out.dme_ident(bounded(r.dme.ident));
  out.dme_slant_range_m(r.dme.valid() ? r.dme.slant_range_m : -1.0);
}

bool in(double v, double lo, double hi) { return std::isfinite(v) && v >= lo && v <= hi; }

}  // namespace

std::optional<std::string> truth_from_message(const msg::AircraftState& s, AvionicsTruth& t) {
  const auto v3 = [](const std::array<double, 3>& a) { return Eigen::Vector3d(a[0], a[1], a[2]); };
  const auto& q = s.q_ned_from_body();
  AvionicsTruth next;
  next.lat_rad = s.latitude_rad();
  next.lon_rad = s.longitude_rad();
  next.altitude_msl_m = s.altitude_msl_m();
  next.velocity_ned_mps = v3(s.velocity_ned_mps());
  next.q_ned_from_body = Eigen::Quaterniond(q[0], q[1], q[2], q[3]);
  next.euler = {s.phi_rad(), s.theta_rad(), s.psi_rad()};
  next.true_airspeed_mps = s.air().tas_mps();
  next.climb_rate_mps = s.climb_rate_mps();
  next.acceleration_body_mps2 = v3(s.acceleration_body_mps2());
  next.omega_body_radps = v3(s.omega_body_radps());
  next.rotating_earth = s.rotating_earth();
  if (!in(s.mass_kg(), 1e-3, 1e7)) return "mass_kg out of range";
  next.specific_force_body_mps2 = v3(s.force_body_n()) / s.mass_kg();
  if (const auto bad = truth_problem(next); !bad.empty()) return std::string(bad) + " not finite";
  if (!in(next.lat_rad, -units::kHalfPi, units::kHalfPi)) return "latitude_rad out of range";
  if (!in(next.altitude_msl_m, -1000.0, 100000.0)) return "altitude_msl_m out of range";
  if (std::abs(next.q_ned_from_body.norm() - 1.0) > 1e-3) return "q_ned_from_body not a unit quaternion";
  t = next;
  return std::nullopt;
}

void to_message(const AvionicsReadings& r, const RadioSelections& radios, bool gps_denied,
                msg::NavigationState& out) {
  for (std::size_t i = 0; i < r.nav.size(); ++i) fill_receiver(r.nav[i], radios.nav[i], out.nav()[i]);
  auto& adf = out.adf();
  adf.frequency_khz(radios.adf_khz);
  adf.status(to_message(r.adf.status));
  adf.ident(bounded(r.adf.ident));
  adf.relative_bearing_rad(r.adf.valid() ? r.adf.relative_bearing_rad : 0.0);
  out.marker().beacon(r.marker.valid() ? to_message(r.marker.beacon) : msg::MARKER_NONE);
  out.marker().ident(bounded(r.marker.valid() ? r.marker.ident : std::string()));

  auto& ins = out.ins();
  ins.valid(r.ins_valid);
  const auto& p = r.ins.state.position;
  ins.latitude_rad(r.ins_valid ? p.lat_rad : 0.0);
  ins.longitude_rad(r.ins_valid ? p.lon_rad : 0.0);
  ins.altitude_m(r.ins_valid ? p.alt_m : 0.0);
  for (int i = 0; i < 3; ++i) {
    ins.velocity_ned_mps()[i] = r.ins_valid ? r.ins.state.velocity_ned_mps[i] : 0.0;
    ins.position_error_ned_m()[i] = r.ins_valid ? r.ins_errors.position_ned_m[i] : 0.0;
  }
  ins.phi_rad(r.ins_valid ? r.ins.euler.phi_rad : 0.0);
  ins.theta_rad(r.ins_valid ? r.ins.euler.theta_rad : 0.0);
  ins.psi_rad(r.ins_valid ? r.ins.euler.psi_rad : 0.0);
  ins.horizontal_error_m(r.ins_valid ? r.ins_errors.horizontal_position_m : 0.0);

  auto& gps = out.gps();
  const bool fix = r.gps.valid;
  gps.valid(fix);
  gps.denied(gps_denied);
  gps.latitude_rad(fix ? r.gps.position.lat_rad : 0.0);
  gps.longitude_rad(fix ? r.gps.position.lon_rad : 0.0);
  gps.altitude_m(fix ? r.gps.position.alt_m : 0.0);
  gps.satellites_visible(static_cast<uint16_t>(r.gps.satellites_visible));
  gps.satellites_used(static_cast<uint16_t>(r.gps.satellites_used));
  gps.gdop(fix ? r.gps.dop.gdop : 0.0);
  gps.pdop(fix ? r.gps.dop.pdop : 0.0);
  gps.hdop(fix ? r.gps.dop.hdop : 0.0);
  gps.vdop(fix ? r.gps.dop.vdop : 0.0);
  gps.horizontal_error_m(r.gps_horizontal_error_m);

  auto& fd = out.fd();
  fd.lateral_mode(r.fd_lateral == LateralMode::kNavTrack        ? msg::FD_LATERAL_NAV
                  : r.fd_lateral == LateralMode::kHeadingSelect ? msg::FD_LATERAL_HEADING
                                                                : msg::FD_LATERAL_OFF);
  fd.vertical_mode(r.fd_vertical == VerticalMode::kGlideSlopeTrack ? msg::FD_VERTICAL_GLIDESLOPE
                   : r.fd_vertical == VerticalMode::kAltitudeHold  ? msg::FD_VERTICAL_ALTITUDE
                                                                   : msg::FD_VERTICAL_OFF);
  fd.roll_valid(r.fd.roll_valid);
  fd.roll_command_rad(r.fd.roll_valid ? r.fd.roll_command_rad : 0.0);
  fd.pitch_valid(r.fd.pitch_valid);
  fd.pitch_command_rad(r.fd.pitch_valid ? r.fd.pitch_command_rad : 0.0);
}

NavComponent::NavComponent(std::string name, NavSetup setup)
    : Component(std::move(name)),
      aircraft_state_(reads(runtime::topics::aircraft_state)),
      pilot_controls_(reads(runtime::topics::pilot_controls)),
      navigation_state_(writes(runtime::topics::navigation_state, setup.state_qos)),
      setup_(std::move(setup)) {
  stations_ = std::make_unique<DatabaseStationSource>(*setup_.database);
  suite_ = std::make_unique<AvionicsSuite>(*stations_, stations_->all_approaches(), setup_.config);
  suite_->radios() = setup_.initial_radios;
  sample_.aircraft_id(static_cast<uint16_t>(setup_.aircraft_id));
}

void NavComponent::apply_failure(const std::string& target, bool active) {
  AvionicsFailures& f = suite_->failures();
  const auto station = [&](std::string_view prefix, radio::StationComponent component) {
    if (target.rfind(prefix, 0) != 0 || target.size() == prefix.size()) return false;
    f.stations.set_off_air(target.substr(prefix.size()), component, active);
    return true;
  };
  if (target == "nav1") f.nav[0] = active;
  else if (target == "nav2") f.nav[1] = active;
  else if (target == "adf") f.adf = active;
  else if (target == "markers") f.markers = active;
  else if (target == "ins") f.ins = active;
  else if (target == "gps") f.gps_denied = active;
  else if (station("station:", radio::StationComponent::kAll) ||
           station("station-dme:", radio::StationComponent::kDme) ||
           station("station-gs:", radio::StationComponent::kGlideSlope) ||
           station("station-markers:", radio::StationComponent::kMarkers)) {
  } else {
    return;  // another federate's system (engine1, ...)
  }
  log().info("failure {} {}", target, active ? "set" : "cleared");
}

void NavComponent::on_command(const msg::SimCommand& command) {
  switch (command.kind()) {
    case msg::COMMAND_FAILURE:
      apply_failure(command.target().to_string(), command.failure().active());
      break;
    case msg::COMMAND_RADIO_TUNING: {
      const msg::RadioTuning& t = command.radios();
      RadioSelections& radios = suite_->radios();
      if (t.nav1_khz() != 0) radios.nav[0] = {t.nav1_khz(), t.obs1_rad()};
      if (t.nav2_khz() != 0) radios.nav[1] = {t.nav2_khz(), t.obs2_rad()};
      if (t.adf_khz() != 0) radios.adf_khz = t.adf_khz();
      log().info("radios tuned by {}: nav1={} nav2={} adf={} kHz", command.issuer().to_string(),
                 radios.nav[0].frequency_khz, radios.nav[1].frequency_khz, radios.adf_khz);
      break;
    }
    case msg::COMMAND_REPOSITION:
      realign_requested_ = true;
      break;
    default:
      break;
  }
}

void NavComponent::apply_pilot_tuning() {
  const msg::PilotControls* pilot = pilot_controls_.latest();
  if (!pilot || pilot_controls_.updates() == controls_updates_seen_) return;
  controls_updates_seen_ = pilot_controls_.updates();
  const msg::RadioTuning& t = pilot->radios();
  RadioSelections& radios = suite_->radios();
  msg::RadioTuning& last = last_pilot_tuning_;
  // A field the pilot changed retunes that radio; 0 kHz (not dialled) never does.
  if (t.nav1_khz() != last.nav1_khz() && t.nav1_khz() != 0) radios.nav[0].frequency_khz = t.nav1_khz();
  if (t.nav2_khz() != last.nav2_khz() && t.nav2_khz() != 0) radios.nav[1].frequency_khz = t.nav2_khz();
  if (t.adf_khz() != last.adf_khz() && t.adf_khz() != 0) radios.adf_khz = t.adf_khz();
  if (t.obs1_rad() != last.obs1_rad() && std::isfinite(t.obs1_rad())) radios.nav[0].obs_course_magnetic_rad = t.obs1_rad();
  if (t.obs2_rad() != last.obs2_rad() && std::isfinite(t.obs2_rad())) radios.nav[1].obs_course_magnetic_rad = t.obs2_rad();
  last = t;
}

bool NavComponent::take_aircraft_state(const runtime::FrameContext& frame) {
  const msg::AircraftState* state = aircraft_state_.latest();
  if (!state || aircraft_state_.updates() == state_updates_seen_) return false;
  state_updates_seen_ = aircraft_state_.updates();
  if (const auto problem = truth_from_message(*state, truth_)) {
    report_fault("input_rejected", "frame " + std::to_string(frame.frame) +
                                       ": aircraft_state of frame " +
                                       std::to_string(state->stamp().frame()) + " " + *problem +
                                       " (kept the previous state)");
    return false;
  }
  have_truth_ = true;
  return true;
}

void NavComponent::step(const runtime::FrameContext& frame) {
  if (frame.resetting() || realign_requested_) {
    // The flight federate moves the aircraft in this frame: the state it writes now, read in
    // the next frame, is where the INS must start again.
    realign_at_frame_ = frame.frame + 1;
    realign_requested_ = false;
  }
  apply_pilot_tuning();
  const double previous_time_s = truth_time_s_;
  const bool fresh = take_aircraft_state(frame);
  if (!have_truth_) return;  // nothing to navigate on yet: write nothing rather than zeros
  truth_time_s_ = aircraft_state_.latest()->stamp().sim_time_s();
  // The INS integrates over the time between the two states it saw: 0 when frozen, stale, or
  // aligned on this very state.
  double dt_s = fresh ? std::max(0.0, truth_time_s_ - previous_time_s) : 0.0;
  if (!suite_->aligned() || frame.frame == realign_at_frame_) {
    suite_->align(truth_);
    dt_s = 0.0;
  }
  const AvionicsReadings& readings = suite_->step(truth_, std::min(dt_s, 1.0), truth_time_s_);
  to_message(readings, suite_->radios(), suite_->failures().gps_denied, sample_);
  sample_.stamp(frame.stamp());
  navigation_state_.write(sample_);
}

runtime::FederateProgram program() {
  struct Options {
    std::string db;
    double nav1_mhz = 0.0, nav2_mhz = 0.0, obs1_deg = 0.0, obs2_deg = 0.0, adf_khz = 0.0;
    std::string ins_grade = "navigation";
    std::uint64_t seed = 1;
    double gps_time_s = 0.0;
    int aircraft_id = 0;
    std::string state_qos;
  };
  auto o = std::make_shared<Options>();
  runtime::FederateProgram p;
  p.program = "fedsim-nav";
  p.default_name = "nav";
  p.description = "navigation and avionics: VOR/ILS/DME, ADF, markers, GPS, INS, flight director";
  p.add_options = [o](CLI::App& app) {
    app.add_option("--db", o->db, "navigation database (default: the one the build made)");
    app.add_option("--nav1-mhz", o->nav1_mhz, "NAV1 frequency at start [MHz] (0 = not tuned)")
        ->check(fedsim::util::FiniteRange(0.0, 117.95));
    app.add_option("--nav2-mhz", o->nav2_mhz, "NAV2 frequency at start [MHz]")
        ->check(fedsim::util::FiniteRange(0.0, 117.95));
    app.add_option("--obs1-deg", o->obs1_deg, "NAV1 course selector at start, magnetic [deg]")
        ->check(fedsim::util::FiniteRange(0.0, 360.0));
    app.add_option("--obs2-deg", o->obs2_deg, "NAV2 course selector at start, magnetic [deg]")
        ->check(fedsim::util::FiniteRange(0.0, 360.0));
    app.add_option("--adf-khz", o->adf_khz, "ADF frequency at start [kHz]")
        ->check(fedsim::util::FiniteRange(0.0, 1750.0));
    app.add_option("--ins-grade", o->ins_grade, "INS sensor errors: perfect | navigation | tactical")
        ->check(CLI::IsMember({"perfect", "navigation", "tactical"}))
        ->capture_default_str();
    app.add_option("--seed", o->seed, "seed of the INS sensor errors and GPS noise")
        ->capture_default_str();
    app.add_option("--gps-time-s", o->gps_time_s,
                   "GPS time at sim time 0, seconds after the constellation epoch")
        ->check(fedsim::util::FiniteRange(0.0, 1e10));
    app.add_option("--state-qos", o->state_qos,
                   "QoS profile of fedsim/navigation_state (default: the catalogue's, state)");
    app.add_option("--aircraft-id", o->aircraft_id, "aircraft id (topic key)")
        ->check(fedsim::util::FiniteRange(0, 65535))
        ->capture_default_str();
  };
  p.make_component = [o](const runtime::FederateOptions& common) {
    NavSetup setup;
    setup.database = std::make_unique<NavDatabase>(
        NavDatabase::open(o->db.empty() ? default_database_path() : o->db));
    if (o->ins_grade == "navigation") {
      setup.config.ins.imu_errors = ImuErrors::sample(ImuErrorSpec::navigation_grade(), o->seed);
    } else if (o->ins_grade == "tactical") {
      setup.config.ins.imu_errors = ImuErrors::sample(ImuErrorSpec::tactical_grade(), o->seed);
    }
    setup.config.ins.noise_seed = o->seed;
    setup.config.gps.pseudoranges.seed = o->seed;
    setup.config.gps_time_at_start_s = o->gps_time_s;
    setup.initial_radios.nav[0] = {static_cast<std::uint32_t>(std::lround(o->nav1_mhz * 20.0)) * 50u,
                                   o->obs1_deg * units::kDegToRad};
    setup.initial_radios.nav[1] = {static_cast<std::uint32_t>(std::lround(o->nav2_mhz * 20.0)) * 50u,
                                   o->obs2_deg * units::kDegToRad};
    setup.initial_radios.adf_khz = static_cast<std::uint32_t>(std::lround(o->adf_khz));
    setup.aircraft_id = o->aircraft_id;
    setup.state_qos = o->state_qos;
    return std::unique_ptr<runtime::Component>(std::make_unique<NavComponent>(common.name, std::move(setup)));
  };
  return p;
}

}  // namespace fedsim::nav
