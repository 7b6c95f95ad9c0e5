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
                   options_.start == "freeze" ? RunState::kFreeze : RunState::kRun) {
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
  const std::uint64_t now = util::monotonic_ns();
  if (now >= next_status_ns_) {  // the once-a-second heartbeat with the frame count
    next_status_ns_ = now + kNsPerS;
    publish_status(msg::FEDERATE_RUNNING, "");
  }
}

bool TimingFederate::status_due_locked() const {
  return !status_messages_.empty() || util::monotonic_ns() >= next_status_ns_;
}

void TimingFederate::on_status(const msg::FederateStatus& status) {
  const std::string name = status.federate().to_string();
  if (name == options_.common.name) return;
  std::lock_guard lock(mutex_);
  switch (status.state()) {
    case msg::FEDERATE_READY:
    case msg::FEDERATE_RUNNING:
      ready_.insert(name);
      break;
    case msg::FEDERATE_STOPPING:
    case msg::FEDERATE_FAILED:
      if (tracker_.expects(name) && started_ && !stopping_) {
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

void TimingFederate::on_command(const msg::SimCommand& command) {
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
  last_ack_ns_[name] = now;
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
  for (const auto& [handle, federate] : writers_) {
    if (handle == status.last_publication_handle && tracker_.expects(federate)) {
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
  log_->error("federate={} lost at frame={}: {}", federate, tracker_.frame(), why);
  const bool completed = tracker_.remove(federate);
  status_messages_.push_back("lost " + federate + ": " + why);  // published by the loop
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

void TimingFederate::check_ack_timeout_locked(std::uint64_t now_ns) {
  if (tracker_.complete()) return;
  const auto timeout_ns = static_cast<std::uint64_t>(options_.ack_timeout_s * kNsPerS);
  for (const auto& name : tracker_.missing()) {
    const auto it = last_ack_ns_.find(name);
    const std::uint64_t since = it != last_ack_ns_.end() ? std::max(it->second, start_ns_) : start_ns_;
    if (now_ns - std::max(since, tick_publish_ns_) >= timeout_ns) {
      mark_lost_locked(name, "no acknowledgement for " + std::to_string(options_.ack_timeout_s) + " s");
    }
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
  start_ns_ = util::monotonic_ns();
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
      check_ack_timeout_locked(now);
    }
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
  std::lock_guard lock(mutex_);
  return summary_;
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
