// fedsim-netem-relay: a userspace stand-in for `tc netem` between two network namespaces.
//
// Why: this machine's kernel has no netem qdisc and no netfilter tools, yet the multi-host test
// must run with loss and delay between "hosts". The relay opens /dev/net/tun twice, creating one
// TAP device in namespace A and one in namespace B (it enters each namespace with setns() before
// TUNSETIFF: a TAP device is created in the caller's namespace, and its file descriptor stays
// valid after the caller leaves it). Every Ethernet frame read from one TAP is written to the
// other after a fixed one-way delay, unless a seeded random draw drops it. Frames are never
// reordered (the delay is the same for all of them), as with `netem delay` without jitter.
//
// The TAP devices live as long as the relay: ending it removes them (no cleanup to forget).
// The caller configures them (addresses, bridge, up) after the relay prints "ready".
// References: Linux Documentation/networking/tuntap.rst; setns(2); netns(8) (/run/netns/NAME).
#include <fcntl.h>
#include <linux/if.h>
#include <linux/if_tun.h>
#include <poll.h>
#include <sched.h>
#include <sys/ioctl.h>
#include <unistd.h>

#include <CLI/CLI.hpp>

#include <array>
#include <atomic>
#include <cctype>
#include <cerrno>
#include <chrono>
#include <csignal>
#include <cstdint>
#include <cstring>
#include <deque>
#include <iostream>
#include <random>
#include <stdexcept>
#include <string>
#include <vector>

#include "common/util/cli_checks.hpp"

namespace {

std::atomic<bool> g_stop{false};
void on_signal(int) { g_stop = true; }

std::runtime_error sys_error(const std::string& what) {
  return std::runtime_error(what + ": " + std::strerror(errno));
}

/// Closes a descriptor when it goes out of scope.
struct Fd {
  int fd = -1;
  explicit Fd(int f) : fd(f) {}
  Fd(const Fd&) = delete;
  Fd& operator=(const Fd&) = delete;
  ~Fd() {
    if (fd >= 0) close(fd);
  }
};

/// Creates TAP device `name` inside network namespace `netns` (a name under /run/netns) and
/// returns its descriptor; the calling thread is back in `home` afterwards.
int open_tap_in(const std::string& netns, const std::string& name, int home) {
  Fd ns(open(("/run/netns/" + netns).c_str(), O_RDONLY | O_CLOEXEC));
  if (ns.fd < 0) throw sys_error("namespace '" + netns + "'");
  if (setns(ns.fd, CLONE_NEWNET) != 0) throw sys_error("setns to '" + netns + "'");
  const int tap = open("/dev/net/tun", O_RDWR | O_CLOEXEC | O_NONBLOCK);
  const int open_errno = errno;
  int result = tap;
  if (tap >= 0) {
    ifreq ifr{};
    ifr.ifr_flags = IFF_TAP | IFF_NO_PI;
    std::strncpy(ifr.ifr_name, name.c_str(), IFNAMSIZ - 1);
    if (ioctl(tap, TUNSETIFF, &ifr) != 0) {
      const int e = errno;
      close(tap);
      setns(home, CLONE_NEWNET);
      errno = e;
      throw sys_error("TUNSETIFF '" + name + "' in '" + netns + "'");
    }
  }
  if (setns(home, CLONE_NEWNET) != 0) throw sys_error("setns back home");
  if (result < 0) {
    errno = open_errno;
    throw sys_error("/dev/net/tun");
  }
  return result;
}

using Clock = std::chrono::steady_clock;

struct Frame {
  Clock::time_point due;
  std::vector<std::uint8_t> bytes;
};

/// One direction of the link: frames read from `from`, delayed, then written to `to`.
struct Direction {
  int from = -1;
  int to = -1;
  std::deque<Frame> queue;
  std::uint64_t seen = 0, dropped = 0, forwarded = 0, write_errors = 0;
};

struct Impairment {
  double loss_fraction = 0.0;
  std::chrono::microseconds delay{0};
  std::mt19937_64 rng;
  std::uniform_real_distribution<double> uniform{0.0, 1.0};
  bool drop() { return loss_fraction > 0.0 && uniform(rng) < loss_fraction; }
};

/// Reads every frame waiting on d.from; queues the survivors.
void read_frames(Direction& d, Impairment& imp) {
  std::array<std::uint8_t, 65536> buffer{};
  for (;;) {
    const ssize_t n = read(d.from, buffer.data(), buffer.size());
    if (n <= 0) return;  // EAGAIN: nothing more now
    ++d.seen;
    if (imp.drop()) {
      ++d.dropped;
      continue;
    }
    d.queue.push_back({Clock::now() + imp.delay, {buffer.begin(), buffer.begin() + n}});
  }
}

/// Writes every queued frame whose delay has passed.
void release_due(Direction& d) {
  const auto now = Clock::now();
  while (!d.queue.empty() && d.queue.front().due <= now) {
    const auto& f = d.queue.front().bytes;
    if (write(d.to, f.data(), f.size()) == static_cast<ssize_t>(f.size())) {
      ++d.forwarded;
    } else {
      ++d.write_errors;  // e.g. the interface is still down: counted, like a lost frame
    }
    d.queue.pop_front();
  }
}

int poll_timeout_ms(const std::array<Direction, 2>& dirs) {
  int timeout = 200;  // wake now and then to notice a stop request
  const auto now = Clock::now();
  for (const auto& d : dirs) {
    if (d.queue.empty()) continue;
    const auto wait = std::chrono::duration_cast<std::chrono::microseconds>(d.queue.front().due - now);
    timeout = std::min(timeout, static_cast<int>(std::max<long long>(0, (wait.count() + 999) / 1000)));
  }
  return timeout;
}

void print_stats(const std::array<Direction, 2>& dirs) {
  const char* names[2] = {"a_to_b", "b_to_a"};
  std::cout << "{";
  for (int i = 0; i < 2; ++i) {
    const auto& d = dirs[i];
    std::cout << (i ? ", " : "") << '"' << names[i] << "\": {\"frames\": " << d.seen
              << ", \"dropped\": " << d.dropped << ", \"forwarded\": " << d.forwarded
              << ", \"write_errors\": " << d.write_errors << "}";
  }
  std::cout << "}" << std::endl;
}

bool valid_name(const std::string& s) {
  if (s.empty() || s.size() >= IFNAMSIZ) return false;
  for (char c : s) {
    if (!(std::isalnum(static_cast<unsigned char>(c)) || c == '-' || c == '_' || c == '.')) return false;
  }
  return true;
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"fedsim-netem-relay: forward Ethernet frames between a TAP device in one network "
               "namespace and one in another, with seeded loss and a fixed one-way delay"};
  std::string ns_a, ns_b, tap_a, tap_b;
  double loss_percent = 0.0, delay_ms = 0.0;
  std::uint64_t seed = 1;
  const auto name_check = CLI::Validator(
      [](const std::string& s) { return valid_name(s) ? std::string{} : "'" + s + "' is not a valid name (1-15 of [A-Za-z0-9._-])"; },
      "NAME");
  app.add_option("--ns-a", ns_a, "network namespace of side A (ip netns name)")->required()->check(name_check);
  app.add_option("--tap-a", tap_a, "TAP device to create in side A")->required()->check(name_check);
  app.add_option("--ns-b", ns_b, "network namespace of side B")->required()->check(name_check);
  app.add_option("--tap-b", tap_b, "TAP device to create in side B")->required()->check(name_check);
  app.add_option("--loss", loss_percent, "percentage of frames dropped, each direction")
      ->check(fedsim::util::FiniteRange(0.0, 100.0))->capture_default_str();
  app.add_option("--delay-ms", delay_ms, "one-way delay added to every frame, each direction")
      ->check(fedsim::util::FiniteRange(0.0, 10000.0))->capture_default_str();
  app.add_option("--seed", seed, "seed of the loss draws (same seed, same drop pattern per frame order)")
      ->capture_default_str();
  CLI11_PARSE(app, argc, argv);

  std::signal(SIGTERM, on_signal);
  std::signal(SIGINT, on_signal);
  try {
    Fd home(open("/proc/self/ns/net", O_RDONLY | O_CLOEXEC));
    if (home.fd < 0) throw sys_error("/proc/self/ns/net");
    Fd a(open_tap_in(ns_a, tap_a, home.fd));
    Fd b(open_tap_in(ns_b, tap_b, home.fd));
    Impairment imp;
    imp.loss_fraction = loss_percent / 100.0;
    imp.delay = std::chrono::microseconds(static_cast<long long>(delay_ms * 1000.0));
    imp.rng.seed(seed);
    std::array<Direction, 2> dirs;
    dirs[0].from = a.fd; dirs[0].to = b.fd;
    dirs[1].from = b.fd; dirs[1].to = a.fd;
    std::cout << "ready: " << ns_a << "/" << tap_a << " <-> " << ns_b << "/" << tap_b
              << " loss=" << loss_percent << "% delay=" << delay_ms << "ms seed=" << seed << std::endl;
    while (!g_stop) {
      std::array<pollfd, 2> fds{{{a.fd, POLLIN, 0}, {b.fd, POLLIN, 0}}};
      if (poll(fds.data(), fds.size(), poll_timeout_ms(dirs)) < 0 && errno != EINTR) {
        throw sys_error("poll");
      }
      for (int i = 0; i < 2; ++i) {
        if (fds[i].revents & POLLIN) read_frames(dirs[i], imp);
      }
      for (auto& d : dirs) release_due(d);
    }
    print_stats(dirs);
  } catch (const std::exception& e) {
    std::cerr << "fedsim-netem-relay: " << e.what() << "\n";
    return 1;
  }
  return 0;
}
