#include "flight/federate/flight_adapter.hpp"

#include "common/instructor/failure_targets.hpp"
#include "common/units/units.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>

namespace fedsim::flight {

namespace {
constexpr double kGradientDepthM = 600.0;  // wind grows with height up to this, then constant

template <class Array>
void copy3(const Eigen::Vector3d& v, Array& out) {
  out[0] = v.x();
  out[1] = v.y();
  out[2] = v.z();
}

std::string describe(const TrimResult& trim) {
  std::ostringstream out;
  out << (trim.converged ? "trimmed" : "trim FAILED: " + trim.reason) << " alt_m=" << trim.altitude_m
      << " tas_mps=" << trim.tas_mps << " alpha_deg=" << trim.alpha_rad / units::kDegToRad;
  return out.str();
}

}  // namespace

AircraftControls controls_from_message(const msg::PilotControls& in, ControlsMode mode,
                                       const AircraftControls& trimmed) {
  AircraftControls c = trimmed;
  const bool relative = mode == ControlsMode::kRelative;
  auto primary = [&](double pilot, double trim) { return relative ? trim + pilot : pilot; };
  c.elevator = primary(in.elevator(), trimmed.elevator);
  c.aileron = primary(in.aileron(), trimmed.aileron);
  c.rudder = primary(in.rudder(), trimmed.rudder);
  for (std::size_t e = 0; e < AircraftControls::kMaxEngines; ++e) {
    c.throttle[e] = primary(in.throttle()[e], trimmed.throttle[e]);
    if (!relative) {
      c.mixture[e] = in.mixture()[e];
      c.propeller[e] = in.propeller()[e];
    }
  }
  if (!relative) {
    c.elevator_trim = in.elevator_trim();
    c.aileron_trim = in.aileron_trim();
    c.rudder_trim = in.rudder_trim();
  }
  c.flaps = relative ? std::max<double>(in.flaps(), trimmed.flaps) : in.flaps();
  c.speedbrake = in.speedbrake();
  c.gear_down = relative ? (in.gear_down() || trimmed.gear_down) : in.gear_down();
  c.brake_left = in.brake_left();
  c.brake_right = in.brake_right();
  c.steering = in.nosewheel_steering();
  return c.clamped();
}

void fill_applied_controls(const AircraftControls& flown, const msg::PilotControls* source,
                           msg::PilotControls& out) {
  if (source != nullptr) {
    out.discretes(source->discretes());
    out.pilot_force_n(source->pilot_force_n());
    out.radios(source->radios());
    out.mcp(source->mcp());
  }
  out.elevator(static_cast<float>(flown.elevator));
  out.aileron(static_cast<float>(flown.aileron));
  out.rudder(static_cast<float>(flown.rudder));
  out.elevator_trim(static_cast<float>(flown.elevator_trim));
  out.aileron_trim(static_cast<float>(flown.aileron_trim));
  out.rudder_trim(static_cast<float>(flown.rudder_trim));
  for (std::size_t e = 0; e < out.throttle().size(); ++e) {
    out.throttle()[e] = static_cast<float>(flown.throttle[e]);
    out.mixture()[e] = static_cast<float>(flown.mixture[e]);
    out.propeller()[e] = static_cast<float>(flown.propeller[e]);
  }
  out.flaps(static_cast<float>(flown.flaps));
  out.speedbrake(static_cast<float>(flown.speedbrake));
  out.gear_down(flown.gear_down);
  out.brake_left(static_cast<float>(flown.brake_left));
  out.brake_right(static_cast<float>(flown.brake_right));
  out.nosewheel_steering(static_cast<float>(flown.steering));
}

void fill_aircraft_state(const AircraftOutputs& out, const AircraftControls& flown,
                         msg::AircraftState& s) {
  s.latitude_rad(out.geodetic.lat_rad);
  s.longitude_rad(out.geodetic.lon_rad);
  s.altitude_msl_m(out.geodetic.alt_m);
  s.height_agl_m(out.height_agl_m);
  copy3(out.position_ecef_m, s.position_ecef_m());
  copy3(out.velocity_ned_mps, s.velocity_ned_mps());
  copy3(out.velocity_body_mps, s.velocity_body_mps());
  for (int i = 0; i < 4; ++i) s.q_ned_from_body()[static_cast<std::size_t>(i)] = out.q_ned_from_body[i];
  s.phi_rad(out.euler.phi_rad);
  s.theta_rad(out.euler.theta_rad);
  s.psi_rad(out.euler.psi_rad);
  copy3(out.omega_body_radps, s.omega_body_radps());
  copy3(out.omega_dot_body_radps2, s.omega_dot_body_radps2());
  copy3(out.acceleration_body_mps2, s.acceleration_body_mps2());
  copy3(out.specific_force_eye_body_mps2, s.specific_force_eye_body_mps2());
  copy3(out.velocity_body_dot_mps2, s.velocity_body_dot_mps2());
  s.load_factor_z(out.load_factor_z);
  s.north_m(out.north_m);
  s.east_m(out.east_m);
  s.ground_speed_mps(out.ground_speed_mps);
  s.climb_rate_mps(out.climb_rate_mps);
  auto& air = s.air();
  air.tas_mps(out.tas_mps);
  air.cas_mps(out.cas_mps);
  air.eas_mps(out.eas_mps);
  air.mach(out.mach);
  air.alpha_rad(out.alpha_rad);
  air.beta_rad(out.beta_rad);
  air.qbar_pa(out.qbar_pa);
  air.static_pressure_pa(out.static_pressure_pa);
  air.temperature_k(out.temperature_k);
  air.density_kgpm3(out.density_kgpm3);
  copy3(out.wind_ned_mps, air.wind_ned_mps());
  air.pressure_altitude_m(out.pressure_altitude_m);
  s.elevator_rad(out.elevator_rad);
  s.aileron_rad(out.aileron_rad);
  s.rudder_rad(out.rudder_rad);
  s.flap_rad(out.flap_rad);
  s.gear_position(out.gear_norm);
  s.flap_norm(out.flap_norm);
  s.speedbrake_norm(out.speedbrake_norm);
  s.spoiler_norm(out.spoiler_norm);
  auto& c = s.controls();
  // The elevator as the surface is commanded: the column plus the trim where the trim is (a
  // trim system moves at its rate towards the trim command, so the command would mislead).
  c.elevator(std::clamp(flown.elevator + out.pitch_trim_norm, -1.0, 1.0));
  c.pitch_trim(out.pitch_trim_norm);
  c.aileron(flown.aileron_command());
  c.rudder(flown.rudder_command());
  for (std::size_t e = 0; e < c.throttle().size(); ++e) c.throttle()[e] = flown.throttle[e];
  c.flaps(flown.flaps);
  c.speedbrake(flown.speedbrake);
  c.gear_down(flown.gear_down);
  c.brake_left(flown.brake_left);
  c.brake_right(flown.brake_right);
  c.steering(flown.steering);
  auto& aero = s.aero();
  aero.lift(out.aero.CL);
  aero.drag(out.aero.CD);
  aero.side(out.aero.CY);
  aero.roll(out.aero.Cl);
  aero.pitch(out.aero.Cm);
  aero.yaw(out.aero.Cn);
  s.stalled(out.stalled);
  copy3(out.total_force_body_n, s.force_body_n());
  copy3(out.total_moment_body_nm, s.moment_body_nm());
  s.mass_kg(out.mass_kg);
  s.fuel_kg(out.fuel_kg);
  copy3(out.cg_m, s.cg_pack_m());
  s.total_thrust_n(out.total_thrust_n);
  s.engine_count(static_cast<uint16_t>(out.engines.size()));
  s.on_ground(out.any_contact);
  s.weight_on_wheels(out.weight_on_wheels);
  s.gear_normal_force_n(out.gear_normal_force_n);
  s.dropped_steps(out.dropped_steps);
  s.rotating_earth(out.rotating_earth);
  const std::size_t n = std::min<std::size_t>(out.contacts.size(), s.gear().size());
  s.gear_count(static_cast<uint16_t>(n));
  for (std::size_t i = 0; i < n; ++i) {
    auto& g = s.gear()[i];
    g.weight_on_wheels(out.contacts[i].weight_on_wheels);
    g.compression_m(static_cast<float>(out.contacts[i].compression_m));
    g.normal_force_n(static_cast<float>(out.contacts[i].normal_force_n));
  }
}

void fill_engine_state(const EngineOutputs& e, std::size_t index, msg::EngineState& s) {
  s.engine_index(static_cast<uint16_t>(index));
  s.running(e.running);
  s.failed(e.failed);
  s.thrust_n(e.thrust_n);
  s.rpm(e.rpm);
  s.propeller_rpm(e.propeller_rpm);
  s.throttle(e.throttle);
  s.starved(e.starved);
  s.n1_pct(e.n1_pct);
  s.n2_pct(e.n2_pct);
  s.manifold_pressure_pa(e.manifold_pressure_pa);
  s.power_w(e.power_w);
  s.fuel_flow_kgps(e.fuel_flow_kgps);
  s.exhaust_temperature_k(e.egt_k);
}

WeatherSettings weather_from_command(const msg::WeatherSettings& in, double surface_elevation_m) {
  WeatherSettings w;
  w.atmosphere.sea_level_temperature_offset_k = in.sea_level_temperature_offset_k();
  if (in.sea_level_pressure_pa() > 0.0) w.atmosphere.sea_level_pressure_pa = in.sea_level_pressure_pa();
  if (in.wind_speed_mps() > 0.0) {
    const double top_speed = in.wind_speed_mps() + in.wind_gradient_mps_per_m() * kGradientDepthM;
    w.wind.altitude_m = {surface_elevation_m, surface_elevation_m + kGradientDepthM};
    w.wind.speed_mps = {in.wind_speed_mps(), std::max(0.0, top_speed)};
    w.wind.from_direction_rad = {in.wind_from_rad(), in.wind_from_rad()};
  }
  const int intensity = static_cast<int>(std::lround(std::clamp(in.turbulence_intensity(), 0.0, 3.0)));
  w.turbulence = static_cast<Turbulence::Severity>(intensity);
  if (in.turbulence_seed() != 0) w.turbulence_seed = in.turbulence_seed();
  w.validate();
  return w;
}

std::string apply_command(const msg::SimCommand& command, AircraftModel& model,
                          const RunwayTable& runways) {
  switch (command.kind()) {
    case msg::COMMAND_REPOSITION: {
      const auto& r = command.reposition();
      if (r.kind() == msg::REPOSITION_POINT) {
        GeodeticPosition p{r.latitude_rad(), r.longitude_rad(), r.altitude_msl_m()};
        const double tas = r.airspeed_mps() > 0 ? r.airspeed_mps() : model.outputs().tas_mps;
        return "reposition to point: " + describe(reposition_to_point(model, p, r.heading_rad(), tas));
      }
      const RunwayEnd end = runways.at(r.airport().to_string(), r.runway().to_string());
      if (r.kind() == msg::REPOSITION_RUNWAY_THRESHOLD) {
        return "reposition to " + end.airport + " " + end.runway + " threshold: " +
               describe(reposition_to_runway(model, runway_of(end)));
      }
      const double distance = r.gate_distance_m() > 0 ? r.gate_distance_m() : 9260.0;  // 5 NM
      const double tas = r.airspeed_mps() > 0 ? r.airspeed_mps() : model.outputs().tas_mps;
      return "reposition to " + end.airport + " " + end.runway + " approach gate: " +
             describe(reposition_to_approach_gate(model, runway_of(end), distance, tas));
    }
    case msg::COMMAND_WEATHER:
      model.set_weather(weather_from_command(command.weather(), model.runway_elevation_m()));
      return "weather set";
    case msg::COMMAND_FAILURE: {
      const std::string target = command.target().to_string();
      const auto owner = instructor::failure_target_owner(target);
      if (owner && *owner != instructor::FailureOwner::kFlight) return {};  // another federate's system
      if (target.rfind("engine", 0) != 0 || target.size() != 7 || target[6] < '1' || target[6] > '4') {
        throw std::invalid_argument("unknown failure target '" + target + "' (" + instructor::failure_targets_description() + ")");
      }
      const std::size_t engine = static_cast<std::size_t>(target[6] - '1');
      if (engine >= model.engine_count()) {
        throw std::invalid_argument(target + ": the aircraft has " +
                                    std::to_string(model.engine_count()) + " engine(s)");
      }
      model.set_engine_failed(engine, command.failure().active());
      return target + (command.failure().active() ? " failed" : " restored");
    }
    default:
      return "";
  }
}

}  // namespace fedsim::flight
