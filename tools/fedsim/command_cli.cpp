#include "fedsim/command_cli.hpp"
#include "common/instructor/failure_targets.hpp"
#include "common/instructor/instructor_request.hpp"
#include "common/runtime/sim_command_codec.hpp"
#include "common/util/cli_checks.hpp"

#include "common/runtime/federate_options.hpp"
#include "common/runtime/publisher.hpp"
#include "common/runtime/shutdown.hpp"
#include "common/runtime/subscription.hpp"

#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <functional>
#include <cmath>
#include <iostream>
#include <thread>
#include <memory>
#include <mutex>
#include <set>

namespace fedsim::launcher {

namespace {

struct CommandOptions {
  runtime::ParticipantOptions dds;
  double wait_s = 5.0;  // an upper bound: it returns once discovery has settled
  instructor::RepositionInput reposition;
  instructor::WeatherInput weather;
  instructor::TuningInput tune;
  instructor::TimeOfDayInput time_of_day;
  std::string tag, channel, lights = "on", system;
};

/// The federates alive on the domain, from their (transient-local) status: every one has a
/// command reader.
class LiveFederates {
 public:
  explicit LiveFederates(const std::shared_ptr<runtime::DdsParticipant>& dds)
      : sub_(dds, runtime::topics::federate_status, runtime::qos::kStatus,
             [this](const msg::FederateStatus& s, const auto&) {
               std::lock_guard lock(mutex_);
               const bool gone = s.state() == msg::FEDERATE_STOPPING ||
                                 s.state() == msg::FEDERATE_FAILED || s.state() == msg::FEDERATE_LOST;
               if (gone) {
                 alive_.erase(s.federate().to_string());
               } else {
                 alive_.insert(s.federate().to_string());
               }
             }) {}
  int count() const {
    std::lock_guard lock(mutex_);
    return static_cast<int>(alive_.size());
  }

 private:
  runtime::Subscription<msg::FederateStatus> sub_;
  mutable std::mutex mutex_;
  std::set<std::string> alive_;
};

/// Waits (at most wait_s) until the command writer has matched the command reader of every
/// federate that reports a status and that number has been stable for a second.
void wait_for_discovery(const runtime::Publisher<msg::SimCommand>& pub, const LiveFederates& live,
                        double wait_s) {
  using clock = std::chrono::steady_clock;
  const auto until = clock::now() + std::chrono::milliseconds(static_cast<int>(wait_s * 1000));
  int seen = -1;
  auto stable_since = clock::now();
  while (clock::now() < until) {
    const int matched = pub.matched_readers();
    if (matched != seen) {
      seen = matched;
      stable_since = clock::now();
    }
    const bool all_known = matched > 0 && matched >= live.count();
    if (all_known && clock::now() - stable_since > std::chrono::seconds(1)) return;
    std::this_thread::sleep_for(std::chrono::milliseconds(10));
  }
}

int send(const CommandOptions& o, msg::SimCommand command) {
  runtime::install_shutdown_handler();
  try {
    auto dds = runtime::DdsParticipant::create(o.dds);
    LiveFederates live(dds);
    runtime::Publisher<msg::SimCommand> pub(dds, runtime::topics::sim_command, runtime::qos::kCommand);
    command.issuer("fedsim-command");
    command.sequence_number(static_cast<uint32_t>(time(nullptr)));
    // Every running federate must get the command before this process, and with it the
    // transient-local history, goes away.
    wait_for_discovery(pub, live, o.wait_s);
    const int readers = pub.matched_readers();
    if (readers == 0) {
      std::cerr << "fedsim command: no federate is listening on domain " << o.dds.domain_id
                << " (sent anyway)\n";
    }
    pub.publish(command);
    // Until every matched reader acknowledged it: "matched" is this writer's side only, and a
    // reader whose side of the match is not complete yet (discovery repaired over a lossy link)
    // drops the sample until it is; the writer repeats it then, but only while this process
    // lives. Once 2 s were seen to be too short (tests/hosts, 20% loss: a command lost, exit 0).
    const double ack_wait_s = std::max(2.0, o.wait_s);
    if (!pub.wait_for_acknowledgments(std::chrono::milliseconds(static_cast<int>(ack_wait_s * 1000)))) {
      std::cerr << "fedsim command: not acknowledged by every reader within " << ack_wait_s
                << " s (a reader that is gone, or one still being discovered, may miss it)\n";
    }
    std::cout << "sent to " << readers << " reader(s)\n";
    return 0;
  } catch (const std::exception& e) {
    std::cerr << "fedsim command: " << e.what() << "\n";
    return 2;
  }
}

/// Checks and sends a request built from the options; a refused one exits 2 naming the field.
int send_request(const CommandOptions& o, const std::function<instructor::InstructorRequest()>& build) {
  instructor::InstructorRequest request;
  try {
    request = build();
  } catch (const instructor::RequestError& e) {
    std::cerr << "fedsim command: " << e.what() << "\n";
    return 2;
  }
  return send(o, runtime::to_sim_command(request));
}

/// The options every `fedsim command` verb takes: DDS domain/QoS and the discovery wait.
void add_common_options(CLI::App& cmd, CommandOptions& o) {
  runtime::add_dds_options(cmd, o.dds);
  cmd.add_option("--wait", o.wait_s, "at most this many seconds to discover the federates")
      ->check(fedsim::util::kFinitePositive)
      ->capture_default_str();
}

void add_simple(CLI::App& parent, std::shared_ptr<CommandOptions> o, int& exit_code,
                const std::string& name, const std::string& help, instructor::InstructorRequest request) {
  auto* cmd = parent.add_subcommand(name, help);
  add_common_options(*cmd, *o);
  cmd->callback([o, request, &exit_code] { exit_code = send_request(*o, [&] { return request; }); });
}
}  // namespace

void add_command_commands(CLI::App& app, int& exit_code) {
  using namespace instructor;
  auto* cmd = app.add_subcommand("command", "send an instructor command to the federation");
  cmd->require_subcommand(1);
  auto o = std::make_shared<CommandOptions>();
  add_simple(*cmd, o, exit_code, "run", "run (simulation time advances)", RunStateRequest{RunState::kRun});
  add_simple(*cmd, o, exit_code, "freeze", "freeze (frames tick, simulation time holds)",
             RunStateRequest{RunState::kFreeze});
  add_simple(*cmd, o, exit_code, "reset", "reset every model to its initial conditions",
             RunStateRequest{RunState::kReset});
  add_simple(*cmd, o, exit_code, "shutdown", "stop every federate cleanly", ShutdownRequest{});

  // Numbers are taken as typed and checked by the instructor library (NaN, range: the field
  // named), the same checks as the instructor station's page and scenario files.
  auto* repo = cmd->add_subcommand("reposition", "move the aircraft: to a runway threshold, an "
                                                 "approach gate (--gate-nm) or a point (--lat ...)");
  add_common_options(*repo, *o);
  auto& r = o->reposition;
  repo->add_option("--airport", r.airport, "ICAO ident, e.g. KSFO");
  repo->add_option("--runway", r.runway, "runway end, e.g. 28R");
  repo->add_option("--gate-nm", r.gate_nm, "approach gate distance from the threshold [NM], up to 30");
  auto* lat = repo->add_option("--lat", r.lat_deg, "point: latitude [deg]");
  repo->add_option("--lon", r.lon_deg, "point: longitude [deg]");
  repo->add_option("--alt-ft", r.alt_ft, "point: altitude MSL [ft]");
  repo->add_option("--heading", r.heading_deg, "point: true heading [deg]");
  repo->add_option("--kt", r.kt, "true airspeed after the move [kt] (0 = keep)");
  repo->add_option("--target", r.target, "aircraft addressed");
  repo->callback([o, lat, &exit_code] {
    o->reposition.point = lat->count() > 0;
    exit_code = send_request(*o, [&] { return InstructorRequest(make_request(o->reposition)); });
  });

  auto* wx = cmd->add_subcommand("weather", "set wind, turbulence and the atmosphere");
  add_common_options(*wx, *o);
  auto& w = o->weather;
  wx->add_option("--wind-from", w.wind_from_deg, "surface wind direction, true [deg]");
  wx->add_option("--wind-kt", w.wind_kt, "surface wind speed [kt]");
  wx->add_option("--gradient-kt-per-1000ft", w.gradient_kt_per_1000ft, "wind increase with height");
  wx->add_option("--turbulence", w.turbulence, "none | light | moderate | severe");
  wx->add_option("--seed", w.seed, "turbulence seed (0 = the flight federate's)");
  wx->add_option("--isa-dev", w.isa_dev_k, "sea-level temperature deviation from ISA [K]");
  wx->add_option("--qnh-hpa", w.qnh_hpa, "sea-level pressure [hPa] (0 = standard)");
  wx->add_option("--visibility-m", w.visibility_m, "visibility [m]");
  wx->add_option("--cloud-base-ft", w.cloud_base_ft, "cloud base [ft] (0 = no cloud)");
  wx->callback([o, &exit_code] {
    exit_code = send_request(*o, [&] { return InstructorRequest(make_request(o->weather)); });
  });

  auto* snap = cmd->add_subcommand("snapshot", "image generators write a PNG of their picture (--snapshot-dir)");
  add_common_options(*snap, *o);
  snap->add_option("--channel", o->channel, "the channel (default: every channel)");
  snap->add_option("--tag", o->tag, "file-name tag [A-Za-z0-9_-]: <channel>_<tag>.png (default: the frame)");
  snap->callback([o, &exit_code] {
    exit_code = send_request(*o, [&] { return InstructorRequest(make_snapshot(o->channel, o->tag)); });
  });

  auto* tod = cmd->add_subcommand("time-of-day", "set the UTC date and time the image generators light the scene by");
  add_common_options(*tod, *o);
  tod->add_option("--utc", o->time_of_day.utc, "YYYY-MM-DDTHH:MM:SS, UTC (e.g. 2026-12-22T01:30:00 is dusk at KSFO: 17:30 PST)")->required();
  tod->add_option("--lights", o->lights, "airport lights")->check(CLI::IsMember({"on", "off"}));
  tod->callback([o, &exit_code] {
    o->time_of_day.lights = o->lights == "on";
    exit_code = send_request(*o, [&] { return InstructorRequest(make_request(o->time_of_day)); });
  });

  auto* tune = cmd->add_subcommand("tune", "tune the aircraft's radios (as the instructor)");
  add_common_options(*tune, *o);
  auto& t = o->tune;
  tune->add_option("--nav1", t.nav1_mhz, "NAV1 frequency [MHz], 108.00-117.95");
  tune->add_option("--obs1", t.obs1_deg, "NAV1 course, magnetic [deg], 0-360");
  tune->add_option("--nav2", t.nav2_mhz, "NAV2 frequency [MHz]");
  tune->add_option("--obs2", t.obs2_deg, "NAV2 course, magnetic [deg]");
  tune->add_option("--adf", t.adf_khz, "ADF frequency [kHz], 190-1750");
  tune->add_option("--target", t.target, "aircraft addressed");
  tune->callback([o, &exit_code] {
    exit_code = send_request(*o, [&] { return InstructorRequest(make_request(o->tune)); });
  });

  for (const bool fail : {true, false}) {
    auto* f = cmd->add_subcommand(fail ? "fail" : "restore",
                                  fail ? "fail a system, e.g. engine1" : "restore a failed system");
    add_common_options(*f, *o);
    f->add_option("system", o->system, std::string("system: ") + failure_targets_description())
        ->required();
    f->callback([o, fail, &exit_code] {
      exit_code = send_request(*o, [&] { return InstructorRequest(make_failure(o->system, fail)); });
    });
  }
}

}  // namespace fedsim::launcher
