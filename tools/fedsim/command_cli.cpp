#include "fedsim/command_cli.hpp"
#include "common/runtime/failure_targets.hpp"
#include "common/util/cli_checks.hpp"
#include "common/units/units.hpp"
#include "visual/model/sun_position.hpp"

#include "common/runtime/federate_options.hpp"
#include "common/runtime/publisher.hpp"
#include "common/runtime/shutdown.hpp"
#include "common/runtime/subscription.hpp"

#include <unistd.h>

#include <chrono>
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
  std::string target;
  // reposition
  std::string airport, runway;
  double gate_nm = 0.0;
  double nav1_mhz = 0, nav2_mhz = 0, obs1_deg = -1, obs2_deg = -1, adf_khz = 0;  // tune
  double lat_deg = 0, lon_deg = 0, alt_ft = 0, heading_deg = 0, kt = 0;
  bool has_point = false;
  // weather
  double wind_from_deg = 0, wind_kt = 0, gradient_kt_per_1000ft = 0, isa_dev_k = 0, qnh_hpa = 0,
         visibility_m = 10000, cloud_base_ft = 0;
  std::string turbulence = "none";
  unsigned seed = 0;
  // snapshot, time of day
  std::string tag, channel, utc, lights = "on";
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
    pub.wait_for_acknowledgments(std::chrono::seconds(2));
    std::cout << "sent to " << readers << " reader(s)\n";
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

/// The options every `fedsim command` verb takes: DDS domain/QoS and the discovery wait.
void add_common_options(CLI::App& cmd, CommandOptions& o) {
  runtime::add_dds_options(cmd, o.dds);
  cmd.add_option("--wait", o.wait_s, "at most this many seconds to discover the federates")
      ->check(fedsim::util::kFinitePositive)
      ->capture_default_str();
}

void add_simple(CLI::App& parent, std::shared_ptr<CommandOptions> o, int& exit_code,
                const std::string& name, const std::string& help, msg::SimCommand command) {
  auto* cmd = parent.add_subcommand(name, help);
  add_common_options(*cmd, *o);
  cmd->callback([o, command, &exit_code] { exit_code = send(*o, command); });
}
}  // namespace

void add_command_commands(CLI::App& app, int& exit_code) {
  auto* cmd = app.add_subcommand("command", "send an instructor command to the federation");
  cmd->require_subcommand(1);
  auto o = std::make_shared<CommandOptions>();
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
  add_common_options(*repo, *o);
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
    r.airspeed_mps(o->kt * units::kKtToMps);
    if (lat->count() > 0) {
      r.kind(msg::REPOSITION_POINT);
      r.latitude_rad(o->lat_deg * units::kDegToRad);
      r.longitude_rad(o->lon_deg * units::kDegToRad);
      r.altitude_msl_m(o->alt_ft * units::kFtToM);
      r.heading_rad(o->heading_deg * units::kDegToRad);
    } else if (!o->airport.empty() && !o->runway.empty()) {
      r.kind(o->gate_nm > 0 ? msg::REPOSITION_APPROACH_GATE : msg::REPOSITION_RUNWAY_THRESHOLD);
      r.airport(o->airport);
      r.runway(o->runway);
      r.gate_distance_m(o->gate_nm * units::kNmToM);
    } else {
      std::cerr << "fedsim command reposition: give --lat/--lon/--alt-ft/--heading, or "
                   "--airport and --runway (and --gate-nm for an approach gate)\n";
      exit_code = 2;
      return;
    }
    exit_code = send(*o, c);
  });

  auto* wx = cmd->add_subcommand("weather", "set wind, turbulence and the atmosphere");
  add_common_options(*wx, *o);
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
    w.wind_from_rad(o->wind_from_deg * units::kDegToRad);
    w.wind_speed_mps(o->wind_kt * units::kKtToMps);
    w.wind_gradient_mps_per_m(o->gradient_kt_per_1000ft * units::kKtToMps / (1000 * units::kFtToM));
    const std::vector<std::string> levels{"none", "light", "moderate", "severe"};
    w.turbulence_intensity(static_cast<double>(
        std::find(levels.begin(), levels.end(), o->turbulence) - levels.begin()));
    w.turbulence_seed(o->seed);
    w.sea_level_temperature_offset_k(o->isa_dev_k);
    w.sea_level_pressure_pa(o->qnh_hpa * 100.0);
    w.visibility_m(o->visibility_m);
    w.cloud_base_m(o->cloud_base_ft * units::kFtToM);
    exit_code = send(*o, c);
  });

  auto* snap = cmd->add_subcommand("snapshot", "image generators write a PNG of their picture (--snapshot-dir)");
  add_common_options(*snap, *o);
  snap->add_option("--channel", o->channel, "the channel (default: every channel)");
  snap->add_option("--tag", o->tag, "file-name tag [A-Za-z0-9_-]: <channel>_<tag>.png (default: the frame)");
  snap->callback([o, &exit_code] {
    if (o->tag.size() > 48 ||
        o->tag.find_first_not_of("abcdefghijklmnopqrstuvwxyzABCDEFGHIJKLMNOPQRSTUVWXYZ0123456789_-") != std::string::npos) {
      std::cerr << "fedsim command snapshot: --tag '" << o->tag << "': up to 48 characters of [A-Za-z0-9_-]\n";
      exit_code = 2;
      return;
    }
    msg::SimCommand c;
    c.kind(msg::COMMAND_SNAPSHOT);
    c.target(o->channel);
    c.snapshot().tag(o->tag);
    c.snapshot().issued_utc_ns(static_cast<unsigned long long>(
        std::chrono::duration_cast<std::chrono::nanoseconds>(std::chrono::system_clock::now().time_since_epoch())
            .count()));
    exit_code = send(*o, c);
  });

  auto* tod = cmd->add_subcommand("time-of-day", "set the UTC date and time the image generators light the scene by");
  add_common_options(*tod, *o);
  tod->add_option("--utc", o->utc, "YYYY-MM-DDTHH:MM:SS, UTC (e.g. 2026-12-22T01:30:00 is dusk at KSFO: 17:30 PST)")->required();
  tod->add_option("--lights", o->lights, "airport lights")->check(CLI::IsMember({"on", "off"}));
  tod->callback([o, &exit_code] {
    msg::SimCommand c;
    c.kind(msg::COMMAND_TIME_OF_DAY);
    const std::optional<visual::UtcTime> utc = visual::parse_utc(o->utc);
    if (!utc) {
      std::cerr << "fedsim command time-of-day: --utc '" << o->utc
                << "': expected YYYY-MM-DDTHH:MM:SS (UTC, years 1800-2200)\n";
      exit_code = 2;
      return;
    }
    c.time_of_day().year(static_cast<std::uint16_t>(utc->year));
    c.time_of_day().month(static_cast<std::uint16_t>(utc->month));
    c.time_of_day().day(static_cast<std::uint16_t>(utc->day));
    c.time_of_day().utc_time_of_day_s(utc->seconds_of_day);
    c.time_of_day().airport_lights_on(o->lights == "on");
    exit_code = send(*o, c);
  });

  auto* tune = cmd->add_subcommand("tune", "tune the aircraft's radios (as the instructor)");
  add_common_options(*tune, *o);
  tune->add_option("--nav1", o->nav1_mhz, "NAV1 frequency [MHz], 108.00-117.95")
      ->check(fedsim::util::FiniteRange(108.0, 117.95));
  tune->add_option("--obs1", o->obs1_deg, "NAV1 course, magnetic [deg]")
      ->check(fedsim::util::FiniteRange(0.0, 360.0));
  tune->add_option("--nav2", o->nav2_mhz, "NAV2 frequency [MHz]")
      ->check(fedsim::util::FiniteRange(108.0, 117.95));
  tune->add_option("--obs2", o->obs2_deg, "NAV2 course, magnetic [deg]")
      ->check(fedsim::util::FiniteRange(0.0, 360.0));
  tune->add_option("--adf", o->adf_khz, "ADF frequency [kHz], 190-1750")
      ->check(fedsim::util::FiniteRange(190.0, 1750.0));
  tune->add_option("--target", o->target, "aircraft addressed");
  tune->callback([o, &exit_code] {
    if (o->nav1_mhz == 0 && o->nav2_mhz == 0 && o->adf_khz == 0) {
      std::cerr << "fedsim command tune: give --nav1, --nav2 or --adf\n";
      exit_code = 2;
      return;
    }
    msg::SimCommand c;
    c.kind(msg::COMMAND_RADIO_TUNING);
    c.target(o->target);
    auto& r = c.radios();
    const auto channel_khz = [](double mhz) {  // the 50 kHz VHF NAV channel dialled
      return static_cast<std::uint32_t>(std::lround(mhz * 20.0)) * 50u;
    };
    r.nav1_khz(o->nav1_mhz > 0 ? channel_khz(o->nav1_mhz) : 0);
    r.nav2_khz(o->nav2_mhz > 0 ? channel_khz(o->nav2_mhz) : 0);
    r.obs1_rad(static_cast<float>(std::max(0.0, o->obs1_deg) * units::kDegToRad));
    r.obs2_rad(static_cast<float>(std::max(0.0, o->obs2_deg) * units::kDegToRad));
    r.adf_khz(static_cast<std::uint32_t>(std::lround(o->adf_khz)));
    exit_code = send(*o, c);
  });

  for (const bool fail : {true, false}) {
    auto* f = cmd->add_subcommand(fail ? "fail" : "restore",
                                  fail ? "fail a system, e.g. engine1" : "restore a failed system");
    add_common_options(*f, *o);
    f->add_option("system", o->target, std::string("system: ") + runtime::failure_targets_description())
        ->required();
    f->callback([o, fail, &exit_code] {
      if (!runtime::failure_target_owner(o->target)) {
        // Refused here: no federate would act on it, and nothing would say so.
        std::cerr << "fedsim command: unknown system '" << o->target << "'; one of: "
                  << runtime::failure_targets_description() << "\n";
        exit_code = 2;
        return;
      }
      msg::SimCommand c;
      c.kind(msg::COMMAND_FAILURE);
      c.target(o->target);
      c.failure().active(fail);
      exit_code = send(*o, c);
    });
  }
}

}  // namespace fedsim::launcher
