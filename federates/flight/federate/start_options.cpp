#include "flight/federate/start_options.hpp"
#include "common/units/units.hpp"
#include "common/util/cli_checks.hpp"

#include "common/airports/runway_table.hpp"

#include <nlohmann/json.hpp>

namespace fedsim::flight {

void add_start_options(CLI::App& app, StartOptions& o) {
  auto* ic = app.add_option("--ic", o.ic_file, "initial-condition file (YAML)");
  auto* trim = app.add_option("--trim", o.trim_kind, "trim: level | climb | turn | ground")
                   ->check(CLI::IsMember({"level", "climb", "turn", "ground"}));
  ic->excludes(trim);
  // Every number is checked here (NaN, infinities, ranges), so a typo is an error naming the
  // option, never a start somewhere absurd (--heading 1e300 used to fly).
  app.add_option("--alt-ft", o.alt_ft, "trim altitude above MSL [ft]")
      ->check(fedsim::util::FiniteRange(-1500.0, 100000.0))->capture_default_str();
  app.add_option("--ktas", o.ktas, "trim true airspeed [kt]")->check(fedsim::util::FiniteRange(1.0, 2000.0));
  app.add_option("--kcas", o.kcas, "trim calibrated airspeed [kt]")->check(fedsim::util::FiniteRange(1.0, 2000.0));
  app.add_option("--heading", o.heading_deg, "true heading [deg]")
      ->check(fedsim::util::FiniteRange(-360.0, 360.0))->capture_default_str();
  app.add_option("--lat", o.lat_deg, "latitude [deg]")->check(fedsim::util::FiniteRange(-90.0, 90.0))->capture_default_str();
  app.add_option("--lon", o.lon_deg, "longitude [deg]")->check(fedsim::util::FiniteRange(-180.0, 180.0))->capture_default_str();
  app.add_option("--gamma-deg", o.gamma_deg, "climb: flight-path angle [deg], + climbing")
      ->check(fedsim::util::FiniteRange(-45.0, 45.0));
  app.add_option("--bank-deg", o.bank_deg, "turn: bank angle [deg], + right")
      ->check(fedsim::util::FiniteRange(-80.0, 80.0));
  app.add_option("--flaps", o.flaps, "flap setting held in the trim, 0..1")->check(fedsim::util::FiniteRange(0.0, 1.0));
  app.add_option("--throttle", o.throttle,
                 "ground start (--trim ground, --airport/--runway): throttle of every engine, "
                 "0 (idle) .. 1 (full), engines settled, brakes set");
  app.add_option("--runway-elevation-m", o.runway_elevation_m, "terrain plane above MSL [m]")
      ->check(fedsim::util::FiniteRange(-500.0, 9000.0));
  app.add_option("--airport", o.airport, "ground start: airport (ICAO), with --runway");
  app.add_option("--runway", o.runway, "ground start: runway end, e.g. 28R");
  app.add_option("--approach-nm", o.approach_nm,
                 "with --airport/--runway: start in level flight this far before the threshold "
                 "(along the extended centreline) at --alt-ft and --kcas/--ktas [NM]")
      ->check(fedsim::util::FiniteRange(0.0, 50.0));
  app.add_option("--approach-offset-nm", o.approach_offset_nm,
                 "approach start: left (+) or right (-) of the extended centreline [NM]")
      ->check(fedsim::util::FiniteRange(-10.0, 10.0))
      ->capture_default_str();
  app.add_option("--intercept-deg", o.intercept_deg,
                 "approach start: heading towards the centreline, degrees off the runway heading")
      ->check(fedsim::util::FiniteRange(0.0, 90.0))
      ->capture_default_str();
  app.add_flag("--gear-down", o.gear_down, "a flight trim with the gear down");
}

namespace {
// --throttle: only for the ground starts, a number within 0..1.
double ground_throttle(const StartOptions& o, bool ground_start) {
  if (!o.throttle) return 0.0;
  if (!ground_start) {
    throw std::invalid_argument(
        "--throttle sets the engines of a ground start (--trim ground or --airport/--runway); "
        "a flight trim solves its throttle, an IC file states its own controls");
  }
  const double t = *o.throttle;
  if (!(t >= 0.0 && t <= 1.0)) {  // NaN fails both comparisons
    throw std::invalid_argument("--throttle: must be a number within 0..1 (got " +
                                std::to_string(t) + ")");
  }
  return t;
}
}  // namespace

namespace {
// --approach-nm with --airport/--runway: level flight before the runway (reposition.hpp).
StartState approach_start_state(const StartOptions& o, AircraftModel& model) {
  if (o.airport.empty() || o.runway.empty()) {
    throw std::invalid_argument("--approach-nm needs --airport and --runway (the runway approached)");
  }
  if (!o.trim_kind.empty() && o.trim_kind != "level") {
    throw std::invalid_argument("--approach-nm starts in level flight: --trim " + o.trim_kind + " does not apply");
  }
  if ((o.ktas > 0) == (o.kcas > 0)) {
    throw std::invalid_argument("an approach start needs exactly one of --ktas or --kcas");
  }
  const RunwayEnd end = RunwayTable::load_default().at(o.airport, o.runway);
  InterceptStart s;
  s.distance_m = *o.approach_nm * units::kNmToM;
  s.left_m = o.approach_offset_nm * units::kNmToM;
  s.intercept_rad = o.intercept_deg * units::kDegToRad;
  s.altitude_msl_m = o.alt_ft * units::kFtToM;
  s.airspeed_is_cas = o.kcas > 0;
  s.airspeed_mps = (o.kcas > 0 ? o.kcas : o.ktas) * units::kKtToMps;
  AircraftControls configuration = model.controls();
  configuration.flaps = o.flaps;
  configuration.gear_down = o.gear_down;
  model.set_controls(configuration);
  StartState start;
  const TrimResult trim = reposition_to_intercept(model, runway_of(end), s);
  start.trim = trim;
  start.initial = trim.initial_conditions;
  start.controls = trim.controls;
  return start;
}
}  // namespace

StartState establish_start(const StartOptions& o, AircraftModel& model) {
  StartState start;
  const bool approach_start = o.ic_file.empty() && o.approach_nm.has_value();
  const bool ground_start = o.ic_file.empty() && !approach_start &&
                            (!o.airport.empty() || !o.runway.empty() || o.trim_kind == "ground");
  const double throttle = ground_throttle(o, ground_start);
  if (!o.ic_file.empty()) {
    const auto file = load_initial_condition_file(o.ic_file);
    if (file.runway_elevation_m) model.set_runway_elevation_m(*file.runway_elevation_m);
    if (o.runway_elevation_m) model.set_runway_elevation_m(*o.runway_elevation_m);
    model.set_weather(file.weather);
    model.reset(file.initial, file.controls);  // engines and surfaces settle for these controls
    start.initial = file.initial;
    start.controls = file.controls;
    return start;
  }
  if (approach_start) return approach_start_state(o, model);
  if (!o.airport.empty() || !o.runway.empty()) {
    const RunwayEnd end = RunwayTable::load_default().at(o.airport, o.runway);
    Runway runway;
    runway.threshold = {end.threshold_lat_rad, end.threshold_lon_rad, end.elevation_m};
    runway.heading_rad = end.heading_rad;
    const TrimResult trim = reposition_to_runway(model, runway, throttle);
    start.trim = trim;
    start.initial = trim.initial_conditions;
    start.controls = trim.controls;
    return start;
  }
  if (o.trim_kind.empty()) {
    throw std::invalid_argument("say how to start: --ic FILE, --trim KIND or --airport/--runway");
  }
  if (o.runway_elevation_m) model.set_runway_elevation_m(*o.runway_elevation_m);
  TrimRequest request;
  request.kind = trim_kind_from_name(o.trim_kind);
  request.position = {o.lat_deg * units::kDegToRad, o.lon_deg * units::kDegToRad, o.alt_ft * units::kFtToM};
  request.heading_rad = o.heading_deg * units::kDegToRad;
  if (request.kind != TrimKind::kGround) {
    if ((o.ktas > 0) == (o.kcas > 0)) {
      throw std::invalid_argument("a flight trim needs exactly one of --ktas or --kcas");
    }
    request.airspeed_is_cas = o.kcas > 0;
    request.airspeed_mps = (o.kcas > 0 ? o.kcas : o.ktas) * units::kKtToMps;
  }
  request.flight_path_rad = o.gamma_deg * units::kDegToRad;
  request.bank_rad = o.bank_deg * units::kDegToRad;
  request.controls.flaps = o.flaps;
  request.controls.gear_down = request.kind == TrimKind::kGround || o.gear_down;
  request.ground_throttle = throttle;
  const TrimResult trim = Trim(model).solve(request);
  start.trim = trim;
  start.initial = trim.initial_conditions;
  start.controls = trim.controls;
  return start;
}

std::string trim_json(const TrimResult& t) {
  nlohmann::json j;
  j["converged"] = t.converged;
  if (!t.converged) j["reason"] = t.reason;
  j["kind"] = std::string(to_string(t.kind));
  j["iterations"] = t.iterations;
  j["alpha_deg"] = t.alpha_rad / units::kDegToRad;
  j["beta_deg"] = t.beta_rad / units::kDegToRad;
  j["phi_deg"] = t.phi_rad / units::kDegToRad;
  j["theta_deg"] = t.theta_rad / units::kDegToRad;
  j["psi_deg"] = t.psi_rad / units::kDegToRad;
  j["flight_path_deg"] = t.flight_path_rad / units::kDegToRad;
  j["turn_rate_dps"] = t.turn_rate_radps / units::kDegToRad;
  j["tas_kt"] = t.tas_mps / units::kKtToMps;
  j["cas_kt"] = t.cas_mps / units::kKtToMps;
  j["altitude_ft"] = t.altitude_m / units::kFtToM;
  j["elevator"] = t.controls.elevator;
  j["aileron"] = t.controls.aileron;
  j["rudder"] = t.controls.rudder;
  j["throttle"] = t.controls.throttle[0];
  j["elevator_deg"] = t.elevator_rad / units::kDegToRad;
  j["aileron_deg"] = t.aileron_rad / units::kDegToRad;
  j["rudder_deg"] = t.rudder_rad / units::kDegToRad;
  j["thrust_n"] = t.total_thrust_n;
  nlohmann::json residuals;
  for (int axis = 0; axis < kTrimAxisCount; ++axis) {
    if (t.constrained[static_cast<std::size_t>(axis)]) {
      residuals[std::string(trim_axis_name(axis))] = t.residuals[static_cast<std::size_t>(axis)];
    }
  }
  j["residuals"] = residuals;
  return j.dump();
}

}  // namespace fedsim::flight
