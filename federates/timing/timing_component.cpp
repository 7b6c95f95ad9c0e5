#include "timing/timing_federate.hpp"

#include "common/runtime/log.hpp"
#include "common/runtime/shutdown.hpp"
#include "common/runtime/sim_command_codec.hpp"
#include "common/util/monotonic_clock.hpp"

#include <nlohmann/json.hpp>
#include <unistd.h>

#include <algorithm>
#include <fstream>
#include <sstream>

namespace fedsim::timing {

namespace {
constexpr std::uint64_t kNsPerS = 1'000'000'000ull;

std::string join(const std::vector<std::string>& names) {
  std::string out;
  for (const auto& n : names) out += (out.empty() ? "" : ",") + n;
  return out;
}
}  // namespace

TimingFederate::TimingFederate(TimingOptions options)
    : options_(std::move(options)),
      tracker_(options_.expect),
      run_control_(1.0 / options_.rate_hz,
                   options_.start == "freeze" ? RunState::kFreeze : RunState::kRun),
      loss_watch_(static_cast<std::uint64_t>(options_.ack_timeout_s * kNsPerS)) {
  runtime::install_shutdown_handler();
  log_ = runtime::make_logger(options_.common.name, options_.common.log_level);
  lockstep_ = options_.mode == "lockstep";
  options_.common.dds.name = options_.common.name;
  dds_ = runtime::DdsParticipant::create(options_.common.dds);
  tick_pub_ = std::make_unique<runtime::Publisher<msg::FrameTick>>(dds_, runtime::topics::frame_tick, runtime::topics::frame_tick.info.default_qos + options_.common.sync_qos_suffix);
  status_pub_ = std::make_unique<runtime::Publisher<msg::FederateStatus>>(
      dds_, runtime::topics::federate_status, runtime::qos::kStatus);
  command_pub_ = std::make_unique<runtime::Publisher<msg::SimCommand>>(
      dds_, runtime::topics::sim_command, runtime::qos::kCommand);
  ack_sub_ = std::make_unique<runtime::Subscription<msg::FrameDone>>(
      dds_, runtime::topics::frame_done, runtime::topics::frame_done.info.default_qos + options_.common.sync_qos_suffix,
      [this](const msg::FrameDone& ack, const auto& info) { on_ack(ack, info); });
  ack_sub_->set_liveliness_handler([this](const auto& status) { on_liveliness(status); });
  status_sub_ = std::make_unique<runtime::Subscription<msg::FederateStatus>>(
      dds_, runtime::topics::federate_status, runtime::qos::kStatus,
      [this](const msg::FederateStatus& status, const auto&) { on_status(status); });
  command_sub_ = std::make_unique<runtime::Subscription<msg::SimCommand>>(
      dds_, runtime::topics::sim_command, runtime::qos::kCommand,
      [this](const msg::SimCommand& command, const auto&) { on_command(command); });
  tick_.frame_period_s(1.0 / options_.rate_hz);
  tick_.mode(lockstep_ ? msg::TIMING_MODE_LOCKSTEP : msg::TIMING_MODE_REALTIME);
  publish_status(msg::FEDERATE_STARTING, "");
}

TimingFederate::~TimingFederate() {
  ack_sub_->close();
  status_sub_->close();
  command_sub_->close();
}

// Never called with mutex_ held: writing delivers to this process's own status reader, whose
// handler takes mutex_ (lock order: DDS entity locks, then mutex_).
void TimingFederate::publish_status(msg::FederateState state, const std::string& message) {
  msg::FederateStatus status;
  status.federate(options_.common.name);
  status.state(state);
  status.message(message.substr(0, 127));
  status.pid(static_cast<uint32_t>(getpid()));
  {
    std::lock_guard lock(mutex_);
    status.frames_done(summary_.frames);
    status.overruns(summary_.overruns);
  }
  status_pub_->publish(status);
}

void TimingFederate::flush_status_messages() {
  std::vector<std::string> messages;
  {
    std::lock_guard lock(mutex_);
    messages.swap(status_messages_);
  }
  for (const auto& m : messages) publish_status(msg::FEDERATE_RUNNING, m);
  publish_lost_statuses();
  const std::uint64_t now = util::monotonic_ns();
  if (now >= next_status_ns_) {  // the once-a-second heartbeat with the frame count
    next_status_ns_ = now + kNsPerS;
    publish_status(msg::FEDERATE_RUNNING, "");
  }
}

/// The lost federate's own status instance, in state LOST (the state the IDL reserves for the
/// timing federate's report): a monitor (fedsim run's progress line, the instructor station)
/// sees it until the federate reports again.
void TimingFederate::publish_lost_statuses() {
  std::vector<std::pair<std::string, std::uint32_t>> lost;
  {
    std::lock_guard lock(mutex_);
    lost.swap(lost_to_publish_);
  }
  for (const auto& [name, pid] : lost) {
    msg::FederateStatus status;
    status.federate(name);
    status.state(msg::FEDERATE_LOST);
    status.message("reported lost by " + options_.common.name);
    status.pid(pid);
    status_pub_->publish(status);
  }
}

bool TimingFederate::status_due_locked() const {
  return !status_messages_.empty() || !lost_to_publish_.empty() ||
         util::monotonic_ns() >= next_status_ns_;
}

double TimingFederate::run_time_s_locked() const {
  return start_ns_ == 0 ? 0.0 : (util::monotonic_ns() - start_ns_) * 1e-9;
}

void TimingFederate::rejoin_locked(const std::string& federate, const std::string& how) {
  tracker_.readmit(federate);
  const std::uint64_t first_frame = tracker_.frame() + 1;
  if (!loss_watch_.record_rejoined(federate, first_frame, run_time_s_locked())) return;
  summary_.rejoined.push_back(federate);
  log_->warn("federate={} rejoined ({}): expected again from frame={}", federate, how, first_frame);
  status_messages_.push_back("rejoined " + federate + " from frame " + std::to_string(first_frame));
}

void TimingFederate::on_status(const msg::FederateStatus& status) {
  const std::string name = status.federate().to_string();
  if (name == options_.common.name) return;
  if (status.state() == msg::FEDERATE_LOST) return;  // a report about it (ours), not from it
  std::lock_guard lock(mutex_);
  const bool member = std::find(options_.expect.begin(), options_.expect.end(), name) !=
                      options_.expect.end();
  switch (status.state()) {
    case msg::FEDERATE_READY:
    case msg::FEDERATE_RUNNING: {
      ready_.insert(name);
      const std::uint32_t old_pid = loss_watch_.pid_of(name);
      const bool replaced = loss_watch_.process_replaced(name, status.pid());
      if (!member || !started_ || stopping_) break;
      // A new process under the name: the old one is gone, even if it was never found silent
      // (a quick restart answers the repeated tick before the acknowledgement timeout).
      if (replaced && !loss_watch_.is_lost(name)) {
        mark_lost_locked(name, "its process (pid " + std::to_string(old_pid) + ") was replaced");
      }
      if (loss_watch_.is_lost(name)) {
        rejoin_locked(name, replaced ? "new process pid " + std::to_string(status.pid())
                                     : "reports again, pid " + std::to_string(status.pid()));
      }
      break;
    }
    case msg::FEDERATE_STOPPING:
    case msg::FEDERATE_FAILED:
      // A member that stops because the federation is told to stop is not lost (the timing
      // federate may see its status before the SHUTDOWN command itself).
      if (member && !loss_watch_.is_lost(name) && started_ && !stopping_ &&
          status.message().to_string().rfind("shutdown command", 0) != 0) {
        mark_lost_locked(name, status.state() == msg::FEDERATE_FAILED
                                   ? "failed: " + status.message().to_string()
                                   : "stopped");
      }
      ready_.erase(name);
      break;
    default:
      break;
  }
  cv_.notify_all();
}

/// Republishes a setting it does not hold yet (decided under holder_mutex_, written outside
/// it: the write may come straight back to this process's own reader, on this thread).
void TimingFederate::hold_command(const msg::SimCommand& command) {
  {
    std::lock_guard lock(holder_mutex_);
    if (!holder_.offer(command)) return;
  }
  log_->info("holding command kind={} target='{}' seq={} from={} for late joiners",
             static_cast<int>(command.kind()), command.target().to_string(),
             command.sequence_number(), command.issuer().to_string());
  command_pub_->publish(command);
}

void TimingFederate::on_command(const msg::SimCommand& command) {
  if (options_.hold_commands) hold_command(command);
  std::lock_guard lock(mutex_);
  if (command.kind() == msg::COMMAND_SHUTDOWN) {
    if (command.issuer().to_string() != options_.common.name) {
      stopping_ = true;
      stop_reason_ = "shutdown command from " + command.issuer().to_string();
    }
  } else if (command.kind() == msg::COMMAND_RUN_STATE) {
    const auto state = command.run_state();
    run_control_.request(state == msg::RUN_STATE_RUN      ? RunState::kRun
                         : state == msg::RUN_STATE_RESET ? RunState::kReset
                                                          : RunState::kFreeze);
    log_->info("run state request={} from={}",
               state == msg::RUN_STATE_RUN ? "run" : state == msg::RUN_STATE_RESET ? "reset" : "freeze",
               command.issuer().to_string());
  }
  cv_.notify_all();
}

void TimingFederate::on_ack(const msg::FrameDone& ack, const runtime::fdds::SampleInfo& info) {
  const std::uint64_t now = util::monotonic_ns();
  std::lock_guard lock(mutex_);
  const std::string name = ack.federate().to_string();
  remember_writer_locked(info.publication_handle, name);
  if (!loss_watch_.is_lost(name)) loss_watch_.acknowledged(name);
  if (!tracker_.acknowledge(name, ack.frame())) return;
  summary_.all_acked.add_ns(now - tick_publish_ns_);
  // Lockstep as fast as possible: issue the next tick right here, on the listener thread.
  if (lockstep_ && options_.scale <= 0.0 && !should_stop_locked()) {
    publish_tick_locked();
  } else {
    cv_.notify_all();
  }
}

void TimingFederate::on_liveliness(const runtime::fdds::LivelinessChangedStatus& status) {
  if (status.not_alive_count_change <= 0) return;
  std::lock_guard lock(mutex_);
  if (!started_ || stopping_) return;
  bool known = false;
  for (const auto& entry : writers_) known |= entry.first == status.last_publication_handle;
  log_->warn("frame_done liveliness: a writer is no longer alive (alive={} not_alive={}, {})",
             status.alive_count, status.not_alive_count,
             known ? "a member's" : "a writer that never acknowledged");
  for (const auto& [handle, federate] : writers_) {
    if (handle == status.last_publication_handle && tracker_.expects(federate) &&
        !loss_watch_.is_lost(federate)) {
      mark_lost_locked(federate, "liveliness lost (process gone or hung)");
    }
  }
}

void TimingFederate::remember_writer_locked(const eprosima::fastrtps::rtps::InstanceHandle_t& handle,
                                            const std::string& federate) {
  // A handful of writers: a linear scan on the acknowledgement path allocates nothing.
  for (const auto& entry : writers_) {
    if (entry.first == handle) return;
  }
  writers_.emplace_back(handle, federate);
}

void TimingFederate::mark_lost_locked(const std::string& federate, const std::string& why) {
  summary_.lost.push_back(federate);
  loss_watch_.record_lost(federate, tracker_.frame(), run_time_s_locked(), why);
  log_->error("federate={} lost at frame={}: {}", federate, tracker_.frame(), why);
  const bool completed = tracker_.remove(federate);
  // Published by the loop: here, under mutex_, a write could deadlock (see publish_status).
  status_messages_.push_back("lost " + federate + " at frame " + std::to_string(tracker_.frame()) +
                             ": " + why);
  lost_to_publish_.emplace_back(federate, loss_watch_.pid_of(federate));
  if (options_.stop_on_lost) {
    stopping_ = true;
    stop_reason_ = "federate " + federate + " lost";
    exit_code_ = 1;
  }
  if (completed) {
    summary_.all_acked.add_ns(util::monotonic_ns() - tick_publish_ns_);
    cv_.notify_all();
  }
}

void TimingFederate::publish_tick_locked() {
  const TickFields f = run_control_.next_tick();
  tick_.frame(f.frame);
  tick_.sim_frame(f.sim_frame);
  tick_.sim_time_s(f.sim_time_s);
  tick_.dt_s(f.dt_s);
  tick_.run_state(runtime::to_msg(f.state));
  tick_.reset_count(f.reset_count);
  tracker_.start_frame(f.frame);
  tick_publish_ns_ = util::monotonic_ns();
  loss_watch_.tick_published(tracker_.expected(), tick_publish_ns_);
  last_resend_ns_ = tick_publish_ns_;
  tick_.publish_time_ns(tick_publish_ns_);
  tick_pub_->publish(tick_);
  ++ticks_published_;
  summary_.frames = ticks_published_;
}

void TimingFederate::republish_tick_locked() {
  last_resend_ns_ = util::monotonic_ns();
  ++summary_.resent_ticks;
  tick_pub_->publish(tick_);
}

bool TimingFederate::frames_exhausted_locked() const {
  return options_.common.max_frames != 0 && ticks_published_ >= options_.common.max_frames;
}

bool TimingFederate::should_stop_locked() const {
  if (stopping_ || runtime::shutdown_requested() || frames_exhausted_locked()) return true;
  return options_.common.duration_s > 0 &&
         util::monotonic_ns() - start_ns_ >= options_.common.duration_s * kNsPerS;
}

/// Silence, measured from the first tick a federate did not acknowledge (model/loss_watch.hpp).
void TimingFederate::check_ack_timeout_locked(std::uint64_t now_ns) {
  for (const auto& name : loss_watch_.overdue(now_ns)) {
    if (!tracker_.expects(name)) continue;
    char why[96];
    std::snprintf(why, sizeof(why), "no acknowledgement for %.2f s (--ack-timeout %g s)",
                  loss_watch_.age_ns(name, now_ns) * 1e-9, options_.ack_timeout_s);
    mark_lost_locked(name, why);
  }
}

bool TimingFederate::wait_for_federation() {
  const auto expected = options_.expect;
  const auto n = static_cast<int>(expected.size());
  const auto until = std::chrono::steady_clock::now() +
                     std::chrono::milliseconds(static_cast<int>(options_.join_timeout_s * 1000));
  log_->info("waiting for federates={} mode={} rate_hz={}", join(expected), options_.mode,
             options_.rate_hz);
  std::unique_lock lock(mutex_);
  for (;;) {
    std::vector<std::string> missing;
    for (const auto& name : expected) {
      if (!ready_.count(name)) missing.push_back(name);
    }
    const bool matched = tick_pub_->matched_readers() >= n && ack_sub_->matched_writers() >= n;
    if (missing.empty() && matched) {
      // Discovery is two-sided: give the other halves of the matches a moment to complete so
      // the first frames' samples reach every reader.
      cv_.wait_for(lock, std::chrono::milliseconds(static_cast<int>(options_.settle_s * 1000)));
      return true;
    }
    if (runtime::shutdown_requested() || stopping_) return false;
    if (std::chrono::steady_clock::now() > until) {
      log_->error("federates not ready after {} s: {}{}", options_.join_timeout_s,
                  missing.empty() ? "(all ready, discovery incomplete)" : join(missing),
                  "; check their logs and that they run on the same domain and QoS profile");
      return false;
    }
    cv_.wait_for(lock, std::chrono::milliseconds(20));
  }
}

int TimingFederate::run() {
  publish_status(msg::FEDERATE_READY, "");
  if (!wait_for_federation()) {
    publish_status(msg::FEDERATE_FAILED, "federation did not assemble");
    return runtime::shutdown_requested() ? 0 : 2;
  }
  log_->info("federation ready: starting ticks");
  publish_status(msg::FEDERATE_RUNNING, "");
  {
    std::lock_guard lock(mutex_);
    start_ns_ = util::monotonic_ns();
    started_ = true;
  }
  if (lockstep_) {
    run_lockstep();
  } else {
    run_realtime();
  }
  end_ns_ = util::monotonic_ns();
  {
    std::lock_guard lock(mutex_);
    stopping_ = true;
    summary_.wall_s = (end_ns_ - start_ns_) * 1e-9;
  }
  if (stop_reason_.empty()) stop_reason_ = runtime::shutdown_requested() ? "signal" : "done";
  log_->info("stopping reason=\"{}\"", stop_reason_);
  const std::string json = summary_json();
  std::printf("%s\n", json.c_str());
  std::fflush(stdout);
  if (!options_.summary_json.empty()) std::ofstream(options_.summary_json) << json << "\n";
  if (options_.shutdown_on_exit) {
    msg::SimCommand shutdown;
    shutdown.kind(msg::COMMAND_SHUTDOWN);
    shutdown.issuer(options_.common.name);
    command_pub_->publish(shutdown);
    command_pub_->wait_for_acknowledgments(std::chrono::seconds(2));
  }
  publish_status(msg::FEDERATE_STOPPING, stop_reason_);
  tick_pub_->wait_for_acknowledgments(std::chrono::seconds(1));
  status_pub_->wait_for_acknowledgments(std::chrono::seconds(1));
  return exit_code_;
}

void TimingFederate::run_realtime() {
  const auto period_ns = static_cast<std::uint64_t>(kNsPerS / options_.rate_hz);
  const std::uint64_t first = util::monotonic_ns() + period_ns;
  for (std::uint64_t n = 0;; ++n) {
    const std::uint64_t deadline = first + n * period_ns;
    util::sleep_until_ns(deadline);
    std::unique_lock lock(mutex_);
    if (should_stop_locked()) break;
    const std::uint64_t now = util::monotonic_ns();
    if (n > 0 && !tracker_.complete()) {
      ++summary_.overruns;
      if (summary_.overruns <= 10 || summary_.overruns % 100 == 0) {
        log_->warn("overrun frame={} missing={} overruns={}", tracker_.frame(),
                   join(tracker_.missing()), summary_.overruns);
      }
    }
    // Every frame, not only on an overrun: the frame is complete without a lost federate.
    check_ack_timeout_locked(now);
    if (n > 0) summary_.period_error.add_ns(now - deadline);
    publish_tick_locked();
    if (status_due_locked()) {
      lock.unlock();
      flush_status_messages();
    }
  }
  // Give the last frame's acknowledgements a moment to arrive for the statistics.
  std::unique_lock lock(mutex_);
  cv_.wait_for(lock, std::chrono::milliseconds(200), [this] { return tracker_.complete(); });
}

void TimingFederate::run_lockstep() {
  const double period_s = 1.0 / options_.rate_hz;
  const auto resend_ns = static_cast<std::uint64_t>(options_.resend_after_s * kNsPerS);
  std::unique_lock lock(mutex_);
  publish_tick_locked();
  for (;;) {
    cv_.wait_for(lock, std::chrono::milliseconds(10));
    if (status_due_locked()) {
      lock.unlock();
      flush_status_messages();
      lock.lock();
    }
    const std::uint64_t now = util::monotonic_ns();
    if (tracker_.complete()) {
      if (should_stop_locked()) break;
      if (options_.scale > 0.0) {
        // Paced lockstep: tick n is due at n * period / scale after the start.
        const auto due = start_ns_ + static_cast<std::uint64_t>(ticks_published_ * period_s /
                                                                options_.scale * kNsPerS);
        if (now < due) {
          lock.unlock();
          util::sleep_until_ns(due);
          lock.lock();
          if (!tracker_.complete()) continue;
        }
      }
      // Frames completed by the listener already have their next tick; this handles the
      // others (paced mode, or completed by dropping a lost federate).
      if (tracker_.complete() && !should_stop_locked()) publish_tick_locked();
      continue;
    }
    if (should_stop_locked() && !frames_exhausted_locked()) break;
    if (now - last_resend_ns_ >= resend_ns) republish_tick_locked();
    check_ack_timeout_locked(now);
  }
}

TimingSummary TimingFederate::summary() const {
  TimingSummary s;
  {
    std::lock_guard lock(mutex_);
    s = summary_;
    s.still_lost = loss_watch_.still_lost();
    s.events = loss_watch_.events();
  }
  std::lock_guard lock(holder_mutex_);
  s.held_settings = holder_.size();
  return s;
}

std::string TimingFederate::summary_json() const {
  const TimingSummary s = summary();
  nlohmann::json j;
  j["federate"] = options_.common.name;
  j["mode"] = options_.mode;
  j["rate_hz"] = options_.rate_hz;
  j["frames"] = s.frames;
  j["wall_s"] = s.wall_s;
  j["frames_per_s"] = s.wall_s > 0 ? s.frames / s.wall_s : 0.0;
  j["overruns"] = s.overruns;
  j["resent_ticks"] = s.resent_ticks;
  j["lost"] = s.lost;
  j["rejoined"] = s.rejoined;
  j["still_lost"] = s.still_lost;
  j["ack_timeout_s"] = options_.ack_timeout_s;
  j["membership"] = nlohmann::json::array();
  for (const auto& e : s.events) {
    nlohmann::json event = {{"event", e.kind == MembershipEvent::Kind::kLost ? "lost" : "rejoined"},
                            {"federate", e.federate},
                            {"frame", e.frame},
                            {"t_s", e.t_s}};
    if (!e.why.empty()) event["why"] = e.why;
    j["membership"].push_back(event);
  }
  j["held_settings"] = s.held_settings;
  j["all_acked_us"] = {{"p50", s.all_acked.percentile_us(50)},
                       {"p99", s.all_acked.percentile_us(99)},
                       {"max", s.all_acked.max_us()},
                       {"count", s.all_acked.count()}};
  j["period_error_us"] = {{"p50", s.period_error.percentile_us(50)},
                          {"p99", s.period_error.percentile_us(99)},
                          {"max", s.period_error.max_us()}};
  return j.dump();
}

}  // namespace fedsim::timing
