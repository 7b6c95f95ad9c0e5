#include "timing/timing_component.hpp"

#include "common/runtime/frame_tick.hpp"
#include "common/runtime/shutdown.hpp"
#include "common/runtime/sim_command_codec.hpp"
#include "common/util/cli_checks.hpp"
#include "common/util/monotonic_clock.hpp"

#include <unistd.h>

#include <cstdio>
#include <fstream>

namespace fedsim::timing {

namespace {
// While the federation assembles, how often the clock looks again.
constexpr std::uint64_t kJoinPollNs = 20'000'000ull;

std::string join_names(const std::vector<std::string>& names) {
  std::string out;
  for (const auto& n : names) out += (out.empty() ? "" : ",") + n;
  return out;
}

MemberState member_state(msg::FederateState state) {
  switch (state) {
    case msg::FEDERATE_STARTING: return MemberState::kStarting;
    case msg::FEDERATE_READY: return MemberState::kReady;
    case msg::FEDERATE_RUNNING: return MemberState::kRunning;
    case msg::FEDERATE_STOPPING: return MemberState::kStopping;
    case msg::FEDERATE_FAILED: return MemberState::kFailed;
    case msg::FEDERATE_LOST: return MemberState::kLost;
  }
  return MemberState::kStarting;
}
}  // namespace

TimekeeperSettings timekeeper_settings(const TimingOptions& o) {
  TimekeeperSettings s;
  s.rate_hz = o.rate_hz;
  if (o.mode != "realtime" && o.mode != "lockstep") {
    throw std::invalid_argument("timing: mode '" + o.mode + "' is not realtime or lockstep");
  }
  s.mode = o.mode == "lockstep" ? ClockMode::kLockstep : ClockMode::kRealtime;
  s.scale = o.scale;
  s.expect = o.expect;
  if (o.start != "run" && o.start != "freeze") {
    throw std::invalid_argument("timing: start '" + o.start + "' is not run or freeze");
  }
  s.start = o.start == "freeze" ? RunState::kFreeze : RunState::kRun;
  s.ack_timeout_s = o.ack_timeout_s;
  s.resend_after_s = o.resend_after_s;
  s.join_timeout_s = o.join_timeout_s;
  s.settle_s = o.settle_s;
  s.stop_on_lost = o.stop_on_lost;
  s.max_frames = o.common.max_frames;
  s.duration_s = o.common.duration_s;
  return s;
}

TimingComponent::TimingComponent(TimingOptions options)
    : Driver(options.common.name),
      options_(std::move(options)),
      ticks_(writes(runtime::topics::frame_tick,
                    std::string(runtime::qos::kTick) + options_.common.sync_qos_suffix)),
      lost_status_(writes(runtime::topics::federate_status)),
      held_commands_(writes(runtime::topics::sim_command)),
      acks_(reads(runtime::topics::frame_done,
                  std::string(runtime::qos::kFrameDone) + options_.common.sync_qos_suffix)),
      statuses_(reads(runtime::topics::federate_status)),
      commands_(reads(runtime::topics::sim_command)),
      keeper_(timekeeper_settings(options_)) {
  acks_.on_arrival([this](const msg::FrameDone& ack, const runtime::WriterId& writer) {
    on_ack(ack, writer, util::monotonic_ns());
  });
  acks_.on_writer_lost([this](const runtime::WriterId& writer) { on_writer_lost(writer, util::monotonic_ns()); });
  statuses_.on_arrival([this](const msg::FederateStatus& status, const runtime::WriterId&) {
    on_status(status, util::monotonic_ns());
  });
  commands_.on_arrival([this](const msg::SimCommand& command, const runtime::WriterId&) { on_command_sample(command); });
}

// ---- Arrivals (middleware threads) ---------------------------------------------------------

void TimingComponent::on_ack(const msg::FrameDone& ack, const runtime::WriterId& writer, std::uint64_t now_ns) {
  std::lock_guard lock(mutex_);
  const std::string name = ack.federate().to_string();
  // A handful of writers: a linear scan on the acknowledgement path allocates nothing.
  bool known = false;
  for (const auto& entry : writers_) known |= entry.first == writer;
  if (!known) writers_.emplace_back(writer, name);
  if (runtime::shutdown_requested()) keeper_.stop("signal");
  switch (keeper_.acknowledge(name, ack.frame(), now_ns)) {
    case Timekeeper::Ack::kTickNow:  // lockstep as fast as possible: the next tick, right here
      publish_tick_locked(now_ns);
      break;
    case Timekeeper::Ack::kCompleted:
      wake();
      break;
    case Timekeeper::Ack::kNothing:
      break;
  }
}

void TimingComponent::on_status(const msg::FederateStatus& status, std::uint64_t now_ns) {
  const std::string name = status.federate().to_string();
  if (name == this->name()) return;
  {
    std::lock_guard lock(mutex_);
    keeper_.status(name, member_state(status.state()), status.pid(), status.message().to_string(), now_ns);
    handle_reports_locked();
  }
  wake();
}

void TimingComponent::on_command_sample(const msg::SimCommand& command) {
  if (options_.hold_commands) hold_command(command);
  {
    std::lock_guard lock(mutex_);
    if (command.kind() == msg::COMMAND_SHUTDOWN) {
      // Its own SHUTDOWN (--shutdown-on-exit) is for the others.
      if (command.issuer().to_string() != name()) {
        keeper_.stop("shutdown command from " + command.issuer().to_string());
      }
    } else if (command.kind() == msg::COMMAND_RUN_STATE) {
      const auto state = command.run_state();
      keeper_.request(runtime::from_msg(state));
      log().info("run state request={} from={}",
                 state == msg::RUN_STATE_RUN ? "run" : state == msg::RUN_STATE_RESET ? "reset" : "freeze",
                 command.issuer().to_string());
    }
  }
  wake();
}

void TimingComponent::on_writer_lost(const runtime::WriterId& writer, std::uint64_t now_ns) {
  {
    std::lock_guard lock(mutex_);
    if (!keeper_.started() || keeper_.stopping()) return;
    bool known = false;
    for (const auto& entry : writers_) known |= entry.first == writer;
    log().warn("frame_done liveliness: a writer is no longer alive ({})",
               known ? "a member's" : "a writer that never acknowledged");
    for (const auto& [id, federate] : writers_) {
      if (id == writer) keeper_.liveliness_lost(federate, now_ns);
    }
    handle_reports_locked();
  }
  wake();
}

/// Republishes a setting it does not hold yet (decided under holder_mutex_, written outside
/// it: the write may come straight back to this process's own reader, on this thread).
void TimingComponent::hold_command(const msg::SimCommand& command) {
  {
    std::lock_guard lock(holder_mutex_);
    if (!holder_.offer(command)) return;
  }
  log().info("holding command kind={} target='{}' seq={} from={} for late joiners",
             static_cast<int>(command.kind()), command.target().to_string(), command.sequence_number(),
             command.issuer().to_string());
  std::lock_guard lock(command_write_mutex_);
  held_commands_.write(command);
}

// ---- The clock (the host's frame thread) ---------------------------------------------------

std::optional<std::uint64_t> TimingComponent::join_locked(std::uint64_t now_ns) {
  if (!waiting_logged_) {
    waiting_logged_ = true;
    log().info("waiting for federates={} mode={} rate_hz={}", join_names(options_.expect), options_.mode,
               options_.rate_hz);
  }
  switch (keeper_.join(now_ns, ticks_.readers(), acks_.writers())) {
    case Timekeeper::Join::kWaiting:
      return now_ns + kJoinPollNs;
    case Timekeeper::Join::kSettling:
      return keeper_.settle_until_ns();
    case Timekeeper::Join::kTimedOut: {
      const auto missing = keeper_.not_ready();
      log().error("federates not ready after {} s: {}{}", options_.join_timeout_s,
                  missing.empty() ? "(all ready, discovery incomplete)" : join_names(missing),
                  "; check their logs and that they run on the same domain and QoS profile");
      fail(runtime::kExitBadInput, "federation did not assemble");
      return std::nullopt;
    }
    case Timekeeper::Join::kReady:
      log().info("federation ready: starting ticks");
      keeper_.start(now_ns);
      return now_ns;
  }
  return now_ns + kJoinPollNs;
}

std::optional<std::uint64_t> TimingComponent::drive(std::uint64_t now_ns) {
  std::optional<std::uint64_t> next;
  {
    std::lock_guard lock(mutex_);
    if (!keeper_.started()) {
      next = join_locked(now_ns);
      if (!next || !keeper_.started()) return next;
    }
    const Timekeeper::Due due = keeper_.wake(now_ns);
    if (due.tick) publish_tick_locked(now_ns);
    if (due.resend) ticks_.write(tick_);
    handle_reports_locked();
    if (due.finished) {
      keeper_.finish(now_ns);
      if (keeper_.exit_code() != 0) fail(keeper_.exit_code(), keeper_.stop_reason());
    } else {
      next = due.next_ns;
    }
  }
  publish_lost_statuses();
  return next;
}

void TimingComponent::publish_tick_locked(std::uint64_t now_ns) {
  tick_ = runtime::tick_of(keeper_.issue_tick(now_ns), 1.0 / options_.rate_hz,
                           keeper_.lockstep() ? msg::TIMING_MODE_LOCKSTEP : msg::TIMING_MODE_REALTIME);
  tick_.publish_time_ns(now_ns);
  ticks_.write(tick_);
}

void TimingComponent::handle_reports_locked() {
  for (const Report& r : keeper_.take_reports()) {
    switch (r.kind) {
      case Report::Kind::kLost:
        log().error("federate={} lost at frame={}: {}", r.federate, r.frame, r.detail);
        note("lost " + r.federate + " at frame " + std::to_string(r.frame) + ": " + r.detail);
        lost_to_publish_.emplace_back(r.federate, r.pid);
        break;
      case Report::Kind::kRejoined:
        log().warn("federate={} rejoined ({}): expected again from frame={}", r.federate, r.detail, r.frame);
        note("rejoined " + r.federate + " from frame " + std::to_string(r.frame));
        break;
      case Report::Kind::kOverrun:
        log().warn("overrun frame={} missing={} overruns={}", r.frame, r.detail, r.overruns);
        break;
    }
  }
}

/// The lost member's own status instance, in state LOST (the state the IDL reserves for the
/// clock's report): a monitor (fedsim run's progress line, the instructor station) sees it
/// until the member reports again.
void TimingComponent::publish_lost_statuses() {
  std::vector<std::pair<std::string, std::uint32_t>> lost;
  {
    std::lock_guard lock(mutex_);
    lost.swap(lost_to_publish_);
  }
  for (const auto& [federate, pid] : lost) {
    msg::FederateStatus status;
    status.federate(federate);
    status.state(msg::FEDERATE_LOST);
    status.message("reported lost by " + name());
    status.pid(pid);
    lost_status_.write(status);
  }
}

runtime::Driver::Progress TimingComponent::progress() const {
  std::lock_guard lock(mutex_);
  return {keeper_.started(), keeper_.frames(), keeper_.overruns()};
}

void TimingComponent::on_stop() {
  bool started = false;
  {
    std::lock_guard lock(mutex_);
    keeper_.finish(util::monotonic_ns());
    started = keeper_.started();
  }
  publish_lost_statuses();
  if (started) {  // a federation that never assembled has no run to sum up
    const std::string json = summary_json();
    std::printf("%s\n", json.c_str());
    std::fflush(stdout);
    if (!options_.summary_json.empty()) std::ofstream(options_.summary_json) << json << "\n";
  }
  if (options_.shutdown_on_exit) {
    msg::SimCommand shutdown;
    shutdown.kind(msg::COMMAND_SHUTDOWN);
    shutdown.issuer(name());
    std::lock_guard lock(command_write_mutex_);
    held_commands_.write(shutdown);
  }
}

TimingSummary TimingComponent::summary() const {
  std::lock_guard lock(mutex_);
  return keeper_.summary();
}

std::string TimingComponent::summary_json() const {
  std::size_t held = 0;
  {
    std::lock_guard lock(holder_mutex_);
    held = holder_.size();
  }
  std::lock_guard lock(mutex_);
  return keeper_.summary_json(name(), held);
}

// ---- The program ---------------------------------------------------------------------------

runtime::FederateProgram program() {
  auto o = std::make_shared<TimingOptions>();
  auto no_hold = std::make_shared<bool>(false);
  runtime::FederateProgram p;
  p.program = "fedsim-timing";
  p.default_name = "timing";
  p.description = "publishes the frame tick (realtime or lockstep)";
  p.add_options = [o, no_hold](CLI::App& app) {
    app.add_option("--rate", o->rate_hz, "frame rate [Hz]")
        ->check(util::FiniteRange(1.0, 10000.0))
        ->capture_default_str();
    app.add_option("--mode", o->mode, "realtime | lockstep")
        ->check(CLI::IsMember({"realtime", "lockstep"}))
        ->capture_default_str();
    app.add_option("--scale", o->scale,
                   "lockstep pacing: 0 = as fast as possible, 1 = real time, 2 = twice real time")
        ->check(util::kFiniteNonNegative);
    app.add_option("--expect", o->expect, "federates that must acknowledge every frame")->delimiter(',');
    app.add_option("--start", o->start, "state of the first frame: run | freeze")
        ->check(CLI::IsMember({"run", "freeze"}))
        ->capture_default_str();
    app.add_option("--ack-timeout", o->ack_timeout_s,
                   "declare a federate lost after this many seconds without acknowledging")
        ->check(util::kFinitePositive)
        ->capture_default_str();
    app.add_option("--resend-after", o->resend_after_s,
                   "lockstep: repeat a tick whose acknowledgements are this many seconds overdue")
        ->check(util::kFinitePositive)
        ->capture_default_str();
    app.add_option("--join-timeout", o->join_timeout_s, "seconds to wait for the expected federates to be ready")
        ->check(util::kFinitePositive)
        ->capture_default_str();
    app.add_option("--settle", o->settle_s, "seconds to let discovery finish once every federate is ready")
        ->check(util::kFiniteNonNegative)
        ->capture_default_str();
    app.add_flag("--stop-on-lost", o->stop_on_lost, "stop when a federate is lost");
    app.add_flag("--shutdown-on-exit", o->shutdown_on_exit,
                 "tell every federate to stop when the timing federate stops");
    app.add_option("--summary-json", o->summary_json, "write the run summary JSON here");
    app.add_flag("--no-hold-commands", *no_hold,
                 "do not keep the latest settings (weather, failures...) for federates that join late");
  };
  p.make_component = [o, no_hold](const runtime::FederateOptions& common) {
    TimingOptions options = *o;
    options.common = common;
    options.hold_commands = !*no_hold;
    return std::unique_ptr<runtime::Component>(std::make_unique<TimingComponent>(std::move(options)));
  };
  return p;
}

}  // namespace fedsim::timing
