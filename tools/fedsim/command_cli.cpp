#include "fedsim/command_cli.hpp"

#include "common/runtime/federate_options.hpp"
#include "common/runtime/publisher.hpp"
#include "common/runtime/shutdown.hpp"

#include <unistd.h>

#include <iostream>
#include <memory>

namespace fedsim::launcher {

namespace {
constexpr double kDeg = 3.14159265358979323846 / 180.0;
constexpr double kKt = 1852.0 / 3600.0;
constexpr double kFt = 0.3048;
constexpr double kNm = 1852.0;

struct CommandOptions {
  runtime::ParticipantOptions dds;
  double wait_s = 3.0;
  std::string target;
  // reposition
  std::string airport, runway;
  double gate_nm = 0.0;
  double lat_deg = 0, lon_deg = 0, alt_ft = 0, heading_deg = 0, kt = 0;
  bool has_point = false;
  // weather
  double wind_from_deg = 0, wind_kt = 0, gradient_kt_per_1000ft = 0, isa_dev_k = 0, qnh_hpa = 0,
         visibility_m = 10000, cloud_base_ft = 0;
  std::string turbulence = "none";
  unsigned seed = 0;
};

int send(const CommandOptions& o, msg::SimCommand command) {
  runtime::install_shutdown_handler();
  try {
    auto dds = runtime::DdsParticipant::create(o.dds);
    runtime::Publisher<msg::SimCommand> pub(dds, msg::TOPIC_SIM_COMMAND, "command");
    command.issuer("fedsim-command");
    command.sequence_number(static_cast<uint32_t>(time(nullptr)));
    // Give discovery a moment so that running federates get the command now; late joiners get
    // it anyway from the transient-local history while this process lives.
    pub.wait_for_readers(1, std::chrono::milliseconds(static_cast<int>(o.wait_s * 1000)));
    if (pub.matched_readers() == 0) {
      std::cerr << "fedsim command: no federate is listening on domain " << o.dds.domain_id
                << " (sent anyway)\n";
    }
    pub.publish(command);
    pub.wait_for_acknowledgments(std::chrono::seconds(2));
    std::cout << "sent to " << pub.matched_readers() << " reader(s)\n";
    return 0;
  } catch (const std::exception& e) {
    std::cerr << "fedsim command: " << e.what() << "\n";
    return 2;
  }
}

msg::SimCommand run_state(msg::RunState s) {
  msg::SimCommand c;
  c.kind(msg::COMMAND_RUN_STATE);
  c.run_state(s);
  return c;
}

void add_simple(CLI::App& parent, std::shared_ptr<CommandOptions> o, int& exit_code,
                const std::string& name, const std::string& help, msg::SimCommand command) {
  auto* cmd = parent.add_subcommand(name, help);
  runtime::add_dds_options(*cmd, o->dds);
  cmd->callback([o, command, &exit_code] { exit_code = send(*o, command); });
}
}  // namespace

void add_command_commands(CLI::App& app, int& exit_code) {
  auto* cmd = app.add_subcommand("command", "send an instructor command to the federation");
  cmd->require_subcommand(1);
  auto o = std::make_shared<CommandOptions>();
  cmd->add_option("--wait", o->wait_s, "seconds to wait for federates to be discovered")
      ->capture_default_str();
  add_simple(*cmd, o, exit_code, "run", "run (simulation time advances)", run_state(msg::RUN_STATE_RUN));
  add_simple(*cmd, o, exit_code, "freeze", "freeze (frames tick, simulation time holds)",
             run_state(msg::RUN_STATE_FREEZE));
  add_simple(*cmd, o, exit_code, "reset", "reset every model to its initial conditions",
             run_state(msg::RUN_STATE_RESET));
  msg::SimCommand shutdown;
  shutdown.kind(msg::COMMAND_SHUTDOWN);
  add_simple(*cmd, o, exit_code, "shutdown", "stop every federate cleanly", shutdown);

  auto* repo = cmd->add_subcommand("reposition", "move the aircraft: to a runway threshold, an "
                                                 "approach gate (--gate-nm) or a point (--lat ...)");
  runtime::add_dds_options(*repo, o->dds);
  repo->add_option("--airport", o->airport, "ICAO ident, e.g. KSFO");
  repo->add_option("--runway", o->runway, "runway end, e.g. 28R");
  repo->add_option("--gate-nm", o->gate_nm, "approach gate distance from the threshold [NM]");
  auto* lat = repo->add_option("--lat", o->lat_deg, "point: latitude [deg]");
  repo->add_option("--lon", o->lon_deg, "point: longitude [deg]");
  repo->add_option("--alt-ft", o->alt_ft, "point: altitude MSL [ft]");
  repo->add_option("--heading", o->heading_deg, "point: true heading [deg]");
  repo->add_option("--kt", o->kt, "true airspeed after the move [kt] (0 = keep)");
  repo->add_option("--target", o->target, "aircraft addressed");
  repo->callback([o, lat, &exit_code] {
    msg::SimCommand c;
    c.kind(msg::COMMAND_REPOSITION);
    c.target(o->target);
    auto& r = c.reposition();
    r.airspeed_mps(o->kt * kKt);
    if (lat->count() > 0) {
      r.kind(msg::REPOSITION_POINT);
      r.latitude_rad(o->lat_deg * kDeg);
      r.longitude_rad(o->lon_deg * kDeg);
      r.altitude_msl_m(o->alt_ft * kFt);
      r.heading_rad(o->heading_deg * kDeg);
    } else if (!o->airport.empty() && !o->runway.empty()) {
      r.kind(o->gate_nm > 0 ? msg::REPOSITION_APPROACH_GATE : msg::REPOSITION_RUNWAY_THRESHOLD);
      r.airport(o->airport);
      r.runway(o->runway);
      r.gate_distance_m(o->gate_nm * kNm);
    } else {
      std::cerr << "fedsim command reposition: give --lat/--lon/--alt-ft/--heading, or "
                   "--airport and --runway (and --gate-nm for an approach gate)\n";
      exit_code = 2;
      return;
    }
    exit_code = send(*o, c);
  });

  auto* wx = cmd->add_subcommand("weather", "set wind, turbulence and the atmosphere");
  runtime::add_dds_options(*wx, o->dds);
  wx->add_option("--wind-from", o->wind_from_deg, "surface wind direction, true [deg]");
  wx->add_option("--wind-kt", o->wind_kt, "surface wind speed [kt]");
  wx->add_option("--gradient-kt-per-1000ft", o->gradient_kt_per_1000ft, "wind increase with height");
  wx->add_option("--turbulence", o->turbulence, "none | light | moderate | severe")
      ->check(CLI::IsMember({"none", "light", "moderate", "severe"}));
  wx->add_option("--seed", o->seed, "turbulence seed (0 = the flight federate's)");
  wx->add_option("--isa-dev", o->isa_dev_k, "sea-level temperature deviation from ISA [K]");
  wx->add_option("--qnh-hpa", o->qnh_hpa, "sea-level pressure [hPa] (0 = standard)");
  wx->add_option("--visibility-m", o->visibility_m, "visibility [m]");
  wx->add_option("--cloud-base-ft", o->cloud_base_ft, "cloud base [ft]");
  wx->callback([o, &exit_code] {
    msg::SimCommand c;
    c.kind(msg::COMMAND_WEATHER);
    auto& w = c.weather();
    w.wind_from_rad(o->wind_from_deg * kDeg);
    w.wind_speed_mps(o->wind_kt * kKt);
    w.wind_gradient_mps_per_m(o->gradient_kt_per_1000ft * kKt / (1000 * kFt));
    const std::vector<std::string> levels{"none", "light", "moderate", "severe"};
    w.turbulence_intensity(static_cast<double>(
        std::find(levels.begin(), levels.end(), o->turbulence) - levels.begin()));
    w.turbulence_seed(o->seed);
    w.sea_level_temperature_offset_k(o->isa_dev_k);
    w.sea_level_pressure_pa(o->qnh_hpa * 100.0);
    w.visibility_m(o->visibility_m);
    w.cloud_base_m(o->cloud_base_ft * kFt);
    exit_code = send(*o, c);
  });

  for (const bool fail : {true, false}) {
    auto* f = cmd->add_subcommand(fail ? "fail" : "restore",
                                  fail ? "fail a system, e.g. engine1" : "restore a failed system");
    runtime::add_dds_options(*f, o->dds);
    f->add_option("system", o->target, "system: engine1..engine4")->required();
    f->callback([o, fail, &exit_code] {
      msg::SimCommand c;
      c.kind(msg::COMMAND_FAILURE);
      c.target(o->target);
      c.failure().active(fail);
      exit_code = send(*o, c);
    });
  }
}

}  // namespace fedsim::launcher
