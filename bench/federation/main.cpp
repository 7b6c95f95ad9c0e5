// fedsim-bench-federation: frame-exchange speed of a fedsim federation on this host.
//
// Starts N synthetic federates (the runtime's frame loop, each publishing a state sample every
// frame) plus the timing federate, as separate processes on 127.0.0.1, and measures:
//   - lockstep as fast as possible: frames per second and tick -> all-acknowledged latency;
//   - realtime at 50 Hz and 100 Hz: period error, overruns, tick -> all-acknowledged latency;
//   - a raw UDP loopback ping-pong between two processes (800-byte packets, as the seed's
//     protocol sends) in the same run, as the floor any middleware sits on;
//   - optionally the seed's own UDP protocol (--seedproto PATH: the seedproto program built from
//     the project's shared tools) back to back, since these VMs lose CPU to their host at random;
//   - CPU steal during each phase (/proc/stat), which explains most of the tails here.
// The last line of output is one JSON object with every figure.
#include "common/util/child_process.hpp"
#include "common/util/build_paths.hpp"
#include "common/util/cli_checks.hpp"
#include "common/util/latency_stats.hpp"
#include "common/util/monotonic_clock.hpp"

#include <CLI/CLI.hpp>
#include <nlohmann/json.hpp>

#include <arpa/inet.h>
#include <netinet/in.h>
#include <sys/socket.h>
#include <sys/wait.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <iostream>
#include <sstream>
#include <thread>

using fedsim::util::ChildProcess;
using json = nlohmann::json;

namespace {

struct Options {
  int federates = 9;
  std::uint64_t lockstep_frames = 20000;
  double realtime_s = 60.0;
  int first_domain = 200;
  std::string seedproto;
  std::string qos_file = fedsim::util::qos_file();
  std::string profile = "fedsim_loopback";
  std::string sync_qos = "best_effort";
  bool skip_realtime = false;
  bool no_state = false;  // followers only acknowledge (as the plain DDS star does)
};

std::string bin_dir() {
  return std::filesystem::read_symlink("/proc/self/exe").parent_path().string();
}

/// Hypervisor steal, summed over CPUs [ms] (USER_HZ = 100 on Linux).
double steal_ms() {
  std::ifstream stat("/proc/stat");
  std::string cpu;
  long long v[8] = {};
  stat >> cpu >> v[0] >> v[1] >> v[2] >> v[3] >> v[4] >> v[5] >> v[6] >> v[7];
  return static_cast<double>(v[7]) * 10.0;
}

json run_federation(const Options& o, const std::string& mode, double rate_hz, int domain,
                    const std::string& dir) {
  std::vector<std::unique_ptr<ChildProcess>> children;
  std::string expect;
  const auto common = [&](const std::string& name) {
    return std::vector<std::string>{"--name", name, "--domain", std::to_string(domain),
                                    "--qos-file", o.qos_file, "--participant-profile", o.profile,
                                    "--log-level", "warn", "--sync-qos", o.sync_qos};
  };
  for (int i = 0; i < o.federates; ++i) {
    const std::string name = "f" + std::to_string(i);
    std::vector<std::string> argv{bin_dir() + "/fedsim-synthetic"};
    if (!o.no_state) argv.push_back("--publish");
    for (auto& a : common(name)) argv.push_back(a);
    children.push_back(std::make_unique<ChildProcess>(argv, dir + "/" + name + ".log"));
    expect += (i ? "," : "") + name;
  }
  const std::string summary = dir + "/timing-" + mode + std::to_string(static_cast<int>(rate_hz)) + ".json";
  std::vector<std::string> argv{bin_dir() + "/fedsim-timing", "--mode", mode, "--rate",
                                std::to_string(rate_hz), "--expect", expect, "--shutdown-on-exit",
                                "--summary-json", summary};
  for (auto& a : common("timing")) argv.push_back(a);
  if (mode == "lockstep") {
    argv.push_back("--frames");
    argv.push_back(std::to_string(o.lockstep_frames));
  } else {
    argv.push_back("--duration");
    argv.push_back(std::to_string(o.realtime_s + 1.0));  // + start-up
  }
  const double steal_before = steal_ms();
  ChildProcess timing(argv, dir + "/timing.log");
  const bool done = timing.wait(o.realtime_s + 600);
  const double steal = steal_ms() - steal_before;
  for (auto& c : children) c->wait(10);
  if (!done || timing.exit_code() != 0) {
    std::cerr << "timing federate failed:\n" << timing.output() << "\n";
    return json{{"error", "timing federate failed"}};
  }
  json j = json::parse(fedsim::util::read_file(summary));
  j["steal_ms"] = steal;
  return j;
}

/// Round trips of an 800-byte UDP datagram between two processes on 127.0.0.1.
json udp_ping_pong(int round_trips) {
  constexpr int kBytes = 800;
  auto make_socket = [](sockaddr_in& addr) {
    const int fd = socket(AF_INET, SOCK_DGRAM, 0);
    addr = {};
    addr.sin_family = AF_INET;
    addr.sin_addr.s_addr = htonl(INADDR_LOOPBACK);
    addr.sin_port = 0;
    bind(fd, reinterpret_cast<sockaddr*>(&addr), sizeof(addr));
    socklen_t len = sizeof(addr);
    getsockname(fd, reinterpret_cast<sockaddr*>(&addr), &len);
    return fd;
  };
  sockaddr_in ping_addr{}, pong_addr{};
  const int ping = make_socket(ping_addr);
  const int pong = make_socket(pong_addr);
  const pid_t child = fork();
  char buf[kBytes] = {};
  if (child == 0) {
    for (int i = 0; i < round_trips; ++i) {
      recv(pong, buf, kBytes, 0);
      sendto(pong, buf, kBytes, 0, reinterpret_cast<sockaddr*>(&ping_addr), sizeof(ping_addr));
    }
    _exit(0);
  }
  fedsim::util::LatencyStats rtt;
  for (int i = 0; i < round_trips; ++i) {
    const auto t0 = fedsim::util::monotonic_ns();
    sendto(ping, buf, kBytes, 0, reinterpret_cast<sockaddr*>(&pong_addr), sizeof(pong_addr));
    recv(ping, buf, kBytes, 0);
    rtt.add_ns(fedsim::util::monotonic_ns() - t0);
  }
  waitpid(child, nullptr, 0);
  close(ping);
  close(pong);
  return {{"round_trip_us", {{"p50", rtt.percentile_us(50)}, {"p99", rtt.percentile_us(99)},
                             {"max", rtt.max_us()}}},
          {"round_trips", round_trips}};
}

json run_seedproto(const Options& o, const std::string& dir) {
  const std::string modes = o.skip_realtime ? "afap" : "50,100,afap";
  ChildProcess seed({o.seedproto, "-K", std::to_string(o.federates), "-P", "0", "-f",
                     std::to_string(static_cast<int>(o.realtime_s * 50)), "-a",
                     std::to_string(o.lockstep_frames), "-m", modes},
                    dir + "/seedproto.log");
  if (!seed.wait(3 * o.realtime_s + 300) || seed.exit_code() != 0) {
    return json{{"error", "seedproto failed"}};
  }
  // Its last line is one JSON object.
  std::istringstream lines(seed.output());
  std::string line, last;
  while (std::getline(lines, line)) {
    if (!line.empty() && line[0] == '{') last = line;
  }
  return last.empty() ? json{{"error", "no JSON from seedproto"}} : json::parse(last);
}

json figures(const json& t) {
  if (t.contains("error")) return t;
  return {{"frames", t["frames"]},
          {"frames_per_s", t["frames_per_s"]},
          {"all_acked_us", t["all_acked_us"]},
          {"period_error_us", t["period_error_us"]},
          {"overruns", t["overruns"]},
          {"lost", t["lost"]},
          {"steal_ms", t["steal_ms"]}};
}

}  // namespace

int main(int argc, char** argv) {
  Options o;
  CLI::App app{"fedsim-bench-federation: frame-exchange speed of a fedsim federation"};
  app.add_option("--federates", o.federates, "synthetic federates (plus the timing federate)")
      ->check(fedsim::util::FiniteRange(1, 60))->capture_default_str();
  app.add_option("--frames", o.lockstep_frames, "lockstep frames")->capture_default_str();
  app.add_option("--realtime-seconds", o.realtime_s, "length of each realtime phase")
      ->check(fedsim::util::kFinitePositive)->capture_default_str();
  app.add_option("--domain", o.first_domain, "first of three DDS domains used")
      ->check(fedsim::util::FiniteRange(0, 230))->capture_default_str();
  app.add_option("--participant-profile", o.profile, "participant QoS profile")->capture_default_str();
  app.add_option("--sync-qos", o.sync_qos, "tick/acknowledgement QoS: best_effort | reliable")
      ->check(CLI::IsMember({"best_effort", "reliable"}))->capture_default_str();
  app.add_option("--seedproto", o.seedproto, "also run the seed protocol baseline (path to seedproto)");
  app.add_flag("--lockstep-only", o.skip_realtime, "skip the realtime phases");
  app.add_flag("--no-state", o.no_state,
               "followers publish no state sample (tick and acknowledgement only: the same samples "
               "per frame as a plain DDS lockstep star)");
  CLI11_PARSE(app, argc, argv);

  const std::string dir = fedsim::util::temp_dir("bench-federation");
  json out;
  out["federates"] = o.federates;
  out["host_cpus"] = std::thread::hardware_concurrency();
  out["participant_profile"] = o.profile;
  out["sync_qos"] = o.sync_qos;
  out["state_samples"] = !o.no_state;
  std::cerr << "udp ping-pong baseline...\n";
  out["udp_ping_pong"] = udp_ping_pong(20000);
  std::cerr << "lockstep, " << o.lockstep_frames << " frames, " << o.federates << " federates...\n";
  out["lockstep"] = figures(run_federation(o, "lockstep", 50, o.first_domain, dir));
  if (!o.skip_realtime) {
    std::cerr << "realtime 50 Hz, " << o.realtime_s << " s...\n";
    out["realtime_50hz"] = figures(run_federation(o, "realtime", 50, o.first_domain + 1, dir));
    std::cerr << "realtime 100 Hz, " << o.realtime_s << " s...\n";
    out["realtime_100hz"] = figures(run_federation(o, "realtime", 100, o.first_domain + 2, dir));
  }
  if (!o.seedproto.empty()) {
    std::cerr << "seed protocol baseline (" << o.seedproto << ")...\n";
    out["seedproto"] = run_seedproto(o, dir);
  }
  const auto& l = out["lockstep"];
  if (!l.contains("error")) {
    std::cerr << "lockstep: " << l["frames_per_s"].get<double>() << " frames/s, tick->all-acked p50 "
              << l["all_acked_us"]["p50"].get<double>() << " us p99 "
              << l["all_acked_us"]["p99"].get<double>() << " us\n";
  }
  std::filesystem::remove_all(dir);
  std::cout << out.dump() << std::endl;
  return 0;
}
