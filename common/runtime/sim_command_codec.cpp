#include "common/runtime/sim_command_codec.hpp"

#include <chrono>

namespace fedsim::runtime {

namespace {

using namespace instructor;

msg::RepositionKind to_msg(RepositionRequest::Kind k) {
  switch (k) {
    case RepositionRequest::Kind::kPoint: return msg::REPOSITION_POINT;
    case RepositionRequest::Kind::kRunwayThreshold: return msg::REPOSITION_RUNWAY_THRESHOLD;
    case RepositionRequest::Kind::kApproachGate: return msg::REPOSITION_APPROACH_GATE;
  }
  return msg::REPOSITION_POINT;
}

struct Encode {
  msg::SimCommand& c;
  void operator()(const RunStateRequest& r) const {
    c.kind(msg::COMMAND_RUN_STATE);
    c.run_state(runtime::to_msg(r.state));
  }
  void operator()(const RepositionRequest& r) const {
    c.kind(msg::COMMAND_REPOSITION);
    c.target(r.target);
    auto& m = c.reposition();
    m.kind(to_msg(r.kind));
    m.airport(r.airport);
    m.runway(r.runway);
    m.latitude_rad(r.latitude_rad);
    m.longitude_rad(r.longitude_rad);
    m.altitude_msl_m(r.altitude_msl_m);
    m.heading_rad(r.heading_rad);
    m.airspeed_mps(r.airspeed_mps);
    m.gate_distance_m(r.gate_distance_m);
  }
  void operator()(const WeatherRequest& w) const {
    c.kind(msg::COMMAND_WEATHER);
    auto& m = c.weather();
    m.wind_from_rad(w.wind_from_rad);
    m.wind_speed_mps(w.wind_speed_mps);
    m.wind_gradient_mps_per_m(w.wind_gradient_mps_per_m);
    m.turbulence_intensity(static_cast<double>(w.turbulence_intensity));
    m.turbulence_seed(w.turbulence_seed);
    m.sea_level_temperature_offset_k(w.isa_deviation_k);
    m.sea_level_pressure_pa(w.sea_level_pressure_pa);
    m.visibility_m(w.visibility_m);
    m.cloud_base_m(w.cloud_base_m);
  }
  void operator()(const FailureRequest& f) const {
    c.kind(msg::COMMAND_FAILURE);
    c.target(f.system);
    c.failure().active(f.active);
  }
  void operator()(const TimeOfDayRequest& t) const {
    c.kind(msg::COMMAND_TIME_OF_DAY);
    auto& m = c.time_of_day();
    m.year(static_cast<std::uint16_t>(t.utc.year));
    m.month(static_cast<std::uint16_t>(t.utc.month));
    m.day(static_cast<std::uint16_t>(t.utc.day));
    m.utc_time_of_day_s(t.utc.seconds_of_day);
    m.airport_lights_on(t.airport_lights_on);
  }
  void operator()(const RadioTuningRequest& r) const {
    c.kind(msg::COMMAND_RADIO_TUNING);
    c.target(r.target);
    auto& m = c.radios();
    m.nav1_khz(r.nav1_khz);
    m.nav2_khz(r.nav2_khz);
    // The sample has no "leave" value for a course: 0 (north) when not given, as before.
    m.obs1_rad(static_cast<float>(r.obs1_rad < 0.0 ? 0.0 : r.obs1_rad));
    m.obs2_rad(static_cast<float>(r.obs2_rad < 0.0 ? 0.0 : r.obs2_rad));
    m.adf_khz(r.adf_khz);
  }
  void operator()(const SnapshotRequest& s) const {
    c.kind(msg::COMMAND_SNAPSHOT);
    c.target(s.channel);
    c.snapshot().tag(s.tag);
    c.snapshot().issued_utc_ns(static_cast<unsigned long long>(
        std::chrono::duration_cast<std::chrono::nanoseconds>(
            std::chrono::system_clock::now().time_since_epoch()).count()));
  }
  void operator()(const ShutdownRequest&) const { c.kind(msg::COMMAND_SHUTDOWN); }
};

}  // namespace

msg::RunState to_msg(timing::RunState s) {
  switch (s) {
    case timing::RunState::kRun: return msg::RUN_STATE_RUN;
    case timing::RunState::kFreeze: return msg::RUN_STATE_FREEZE;
    case timing::RunState::kReset: return msg::RUN_STATE_RESET;
  }
  return msg::RUN_STATE_FREEZE;
}

timing::RunState from_msg(msg::RunState s) {
  return s == msg::RUN_STATE_RUN ? timing::RunState::kRun
         : s == msg::RUN_STATE_RESET ? timing::RunState::kReset
                                     : timing::RunState::kFreeze;
}

msg::SimCommand to_sim_command(const InstructorRequest& request) {
  msg::SimCommand c;
  std::visit(Encode{c}, request);
  return c;
}

std::optional<InstructorRequest> from_sim_command(const msg::SimCommand& c) {
  switch (c.kind()) {
    case msg::COMMAND_RUN_STATE:
      return RunStateRequest{from_msg(c.run_state())};
    case msg::COMMAND_REPOSITION: {
      const auto& m = c.reposition();
      RepositionRequest r;
      r.kind = m.kind() == msg::REPOSITION_RUNWAY_THRESHOLD ? RepositionRequest::Kind::kRunwayThreshold
               : m.kind() == msg::REPOSITION_APPROACH_GATE  ? RepositionRequest::Kind::kApproachGate
                                                            : RepositionRequest::Kind::kPoint;
      r.target = c.target().to_string();
      r.airport = m.airport().to_string();
      r.runway = m.runway().to_string();
      r.latitude_rad = m.latitude_rad();
      r.longitude_rad = m.longitude_rad();
      r.altitude_msl_m = m.altitude_msl_m();
      r.heading_rad = m.heading_rad();
      r.airspeed_mps = m.airspeed_mps();
      r.gate_distance_m = m.gate_distance_m();
      return r;
    }
    case msg::COMMAND_WEATHER: {
      const auto& m = c.weather();
      WeatherRequest w;
      w.wind_from_rad = m.wind_from_rad();
      w.wind_speed_mps = m.wind_speed_mps();
      w.wind_gradient_mps_per_m = m.wind_gradient_mps_per_m();
      w.turbulence_intensity = static_cast<int>(m.turbulence_intensity());
      w.turbulence_seed = m.turbulence_seed();
      w.isa_deviation_k = m.sea_level_temperature_offset_k();
      w.sea_level_pressure_pa = m.sea_level_pressure_pa();
      w.visibility_m = m.visibility_m();
      w.cloud_base_m = m.cloud_base_m();
      return w;
    }
    case msg::COMMAND_FAILURE:
      return FailureRequest{c.target().to_string(), c.failure().active()};
    case msg::COMMAND_TIME_OF_DAY: {
      const auto& m = c.time_of_day();
      return TimeOfDayRequest{UtcTime{m.year(), m.month(), m.day(), m.utc_time_of_day_s()},
                              m.airport_lights_on()};
    }
    case msg::COMMAND_RADIO_TUNING: {
      const auto& m = c.radios();
      return RadioTuningRequest{c.target().to_string(), m.nav1_khz(), m.nav2_khz(), m.obs1_rad(),
                                m.obs2_rad(), m.adf_khz()};
    }
    case msg::COMMAND_SNAPSHOT:
      return SnapshotRequest{c.target().to_string(), c.snapshot().tag().to_string()};
    case msg::COMMAND_SHUTDOWN:
      return ShutdownRequest{};
  }
  return std::nullopt;
}

}  // namespace fedsim::runtime
