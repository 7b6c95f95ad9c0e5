#include "common/runtime/federate.hpp"

#include "common/runtime/log.hpp"
#include "common/runtime/shutdown.hpp"
#include "common/util/monotonic_clock.hpp"

#include <unistd.h>

#include <algorithm>

namespace fedsim::runtime {

namespace {
constexpr auto kStatusPeriod = std::chrono::seconds(1);
constexpr auto kInputJoinTimeout = std::chrono::seconds(3);
constexpr auto kLoopWakeup = std::chrono::milliseconds(20);

std::string host_name() {
  char buf[256] = {};
  gethostname(buf, sizeof(buf) - 1);
  return buf;
}

FrameContext context_of(const msg::FrameTick& tick) {
  FrameContext ctx;
  ctx.frame = tick.frame();
  ctx.sim_frame = tick.sim_frame();
  ctx.sim_time_s = tick.sim_time_s();
  ctx.dt_s = tick.dt_s();
  ctx.frame_period_s = tick.frame_period_s();
  ctx.run_state = tick.run_state();
  ctx.reset_count = tick.reset_count();
  ctx.mode = tick.mode();
  return ctx;
}
}  // namespace

Federate::Federate(const FederateOptions& options) : options_(options) {
  install_shutdown_handler();
  log_ = make_logger(options_.name, options_.log_level);
  start_ns_ = util::monotonic_ns();
  options_.dds.name = options_.name;
  dds_ = DdsParticipant::create(options_.dds);
  done_sample_.federate(options_.name);
  frame_done_pub_ = std::make_unique<Publisher<msg::FrameDone>>(dds_, msg::TOPIC_FRAME_DONE,
                                                                "frame_done" + options_.sync_qos_suffix);
  status_pub_ = std::make_unique<Publisher<msg::FederateStatus>>(dds_, msg::TOPIC_FEDERATE_STATUS,
                                                                 "status");
  tick_sub_ = std::make_unique<Subscription<msg::FrameTick>>(
      dds_, msg::TOPIC_FRAME_TICK, "tick" + options_.sync_qos_suffix,
      [this](const msg::FrameTick& tick, const auto&) { handle_tick(tick); });
  command_sub_ = std::make_unique<Subscription<msg::SimCommand>>(
      dds_, msg::TOPIC_SIM_COMMAND, "command",
      [this](const msg::SimCommand& cmd, const auto&) { handle_command(cmd); });
  publish_status(msg::FEDERATE_STARTING, "");
  log_->info("started domain={} profile={} pid={}", options_.dds.domain_id,
             options_.dds.participant_profile, getpid());
}

Federate::~Federate() {
  // Stop deliveries before anything they touch goes away.
  if (tick_sub_) tick_sub_->close();
  if (command_sub_) command_sub_->close();
  endpoints_.clear();
}

double Federate::input_timeout_s() const {
  const double period = pending_tick_.frame_period_s();
  if (pending_tick_.mode() == msg::TIMING_MODE_REALTIME && period > 0.0) {
    return std::min(options_.input_timeout_s, 0.5 * period);
  }
  return options_.input_timeout_s;
}

void Federate::handle_command(const msg::SimCommand& command) {
  if (command.kind() == msg::COMMAND_SHUTDOWN) {
    stop("shutdown command from " + command.issuer().to_string());
    return;
  }
  std::lock_guard lock(command_mutex_);
  commands_.push_back(command);
}

void Federate::handle_tick(const msg::FrameTick& tick) {
  std::lock_guard lock(frame_mutex_);
  if (!accepting_ticks_ || stopping_) return;
  if (stepped_any_ && tick.frame() <= last_frame_) {
    // The timing federate repeats a tick when an acknowledgement went missing: re-acknowledge.
    ++stats_.repeated_ticks;
    if (tick.frame() == last_frame_) publish_done_locked(last_frame_, last_compute_us_, last_latency_ns_);
    return;
  }
  if (pending_ && pending_tick_.frame() == tick.frame()) return;  // a repeat of the pending tick
  if (pending_) ++stats_.skipped_ticks;
  pending_tick_ = tick;
  pending_ = true;
  pending_since_ns_ = util::monotonic_ns();
  step_pending_locked(false);
  if (pending_) frame_cv_.notify_all();  // the loop thread enforces the input timeout
}

void Federate::on_lockstep_input() {
  std::lock_guard lock(frame_mutex_);
  if (pending_ && !stopping_) step_pending_locked(false);
}

bool Federate::inputs_ready_locked(std::uint64_t frame) const {
  const auto needed = static_cast<std::int64_t>(frame) - 1;
  return std::all_of(inputs_.begin(), inputs_.end(), [&](const auto& in) {
    return in->matched_writers() == 0 || in->last_frame.load() >= needed;
  });
}

void Federate::step_pending_locked(bool forced) {
  if (!pending_) return;
  if (!forced && !inputs_ready_locked(pending_tick_.frame())) return;
  if (forced) {
    ++stats_.late_inputs;
    for (const auto& in : inputs_) {
      if (in->matched_writers() > 0 &&
          in->last_frame.load() < static_cast<std::int64_t>(pending_tick_.frame()) - 1) {
        log_->warn("frame={} input={} missing after {:.3f}s: stepping with its last sample",
                   pending_tick_.frame(), in->topic, input_timeout_s());
      }
    }
  }
  pending_ = false;
  const FrameContext ctx = context_of(pending_tick_);

  {
    std::lock_guard lock(command_mutex_);
    commands_now_.swap(commands_);
    commands_.clear();
  }
  const std::uint64_t start_ns = util::monotonic_ns();
  const std::uint64_t latency_ns =
      start_ns > pending_tick_.publish_time_ns() ? start_ns - pending_tick_.publish_time_ns() : 0;
  try {
    if (command_handler_) {
      for (const auto& cmd : commands_now_) command_handler_(cmd);
    }
    step_(ctx);
  } catch (const std::exception& e) {
    log_->error("frame={} step failed: {}", ctx.frame, e.what());
    stopping_ = true;
    fail(std::string("step failed: ") + e.what());
    return;
  }
  const std::uint64_t compute_ns = util::monotonic_ns() - start_ns;
  stats_.compute.add_ns(compute_ns);
  stats_.tick_latency.add_ns(latency_ns);
  window_compute_.add_ns(compute_ns);
  ++stats_.frames;
  if (ctx.frame_period_s > 0 && compute_ns > ctx.frame_period_s * 1e9) ++stats_.overruns;
  stepped_any_ = true;
  last_frame_ = ctx.frame;
  last_compute_us_ = static_cast<float>(compute_ns / 1000.0);
  last_latency_ns_ = latency_ns;
  publish_done_locked(ctx.frame, last_compute_us_, latency_ns);
  if (options_.max_frames != 0 && stats_.frames >= options_.max_frames) {
    stop("stepped " + std::to_string(stats_.frames) + " frames");
  }
}

void Federate::publish_done_locked(std::uint64_t frame, float compute_us,
                                   std::uint64_t latency_ns) {
  done_sample_.frame(frame);
  done_sample_.compute_time_us(compute_us);
  done_sample_.tick_latency_ns(latency_ns);
  frame_done_pub_->publish(done_sample_);
}

void Federate::publish_status(msg::FederateState state, const std::string& message) {
  msg::FederateStatus status;
  status.federate(options_.name);
  status.state(state);
  status.message(message.substr(0, 127));
  status.pid(static_cast<uint32_t>(getpid()));
  status.host(host_name().substr(0, 63));
  {
    std::lock_guard lock(frame_mutex_);
    status.frames_done(stats_.frames);
    status.overruns(stats_.overruns);
    status.compute_mean_us(static_cast<float>(window_compute_.mean_us()));
    status.compute_max_us(static_cast<float>(window_compute_.max_us()));
    window_compute_.reset();
  }
  status.uptime_s((util::monotonic_ns() - start_ns_) * 1e-9);
  status_pub_->publish(status);
}

void Federate::stop(const std::string& reason) {
  if (!stop_requested_.exchange(true)) {
    std::lock_guard lock(command_mutex_);  // not frame_mutex_: stop() may be called from a step
    stop_reason_ = reason;
  }
  frame_cv_.notify_all();
}

void Federate::fail(const std::string& reason) {
  exit_code_.store(1);
  stop(reason);
}

FrameStatistics Federate::statistics() const {
  std::lock_guard lock(frame_mutex_);
  return stats_;
}

void Federate::wait_for_inputs_to_match() {
  const auto until = std::chrono::steady_clock::now() + kInputJoinTimeout;
  std::vector<std::shared_ptr<LockstepInput>> inputs;
  {
    std::lock_guard lock(frame_mutex_);
    inputs = inputs_;
  }
  for (const auto& in : inputs) {
    while (in->matched_writers() == 0 && std::chrono::steady_clock::now() < until &&
           !shutdown_requested()) {
      std::this_thread::sleep_for(std::chrono::milliseconds(10));
    }
    if (in->matched_writers() == 0) {
      log_->warn("input={} has no writer yet: stepping without it until one appears", in->topic);
    }
  }
}

int Federate::run(StepFunction step) {
  step_ = std::move(step);
  wait_for_inputs_to_match();
  {
    std::lock_guard lock(frame_mutex_);
    accepting_ticks_ = true;
  }
  publish_status(msg::FEDERATE_READY, "");
  log_->info("ready");
  loop_until_stop();
  finish();
  return exit_code_.load();
}

void Federate::loop_until_stop() {
  const std::uint64_t deadline_ns =
      options_.duration_s > 0 ? start_ns_ + static_cast<std::uint64_t>(options_.duration_s * 1e9)
                              : 0;
  auto next_status = std::chrono::steady_clock::now() + kStatusPeriod;
  bool announced_running = false;
  while (!stop_requested_.load()) {
    if (shutdown_requested()) {
      stop(shutdown_signal() ? "signal " + std::to_string(shutdown_signal()) : "shutdown");
      break;
    }
    if (deadline_ns != 0 && util::monotonic_ns() >= deadline_ns) {
      stop("duration of " + std::to_string(options_.duration_s) + " s reached");
      break;
    }
    {
      std::unique_lock lock(frame_mutex_);
      frame_cv_.wait_for(lock, kLoopWakeup);
      if (pending_ && !stopping_) {
        const double waited_s = (util::monotonic_ns() - pending_since_ns_) * 1e-9;
        if (waited_s >= input_timeout_s()) step_pending_locked(true);
      }
    }
    if (!announced_running && statistics().frames > 0) {
      announced_running = true;
      publish_status(msg::FEDERATE_RUNNING, "");
    }
    if (std::chrono::steady_clock::now() >= next_status) {
      next_status += kStatusPeriod;
      publish_status(announced_running ? msg::FEDERATE_RUNNING : msg::FEDERATE_READY, "");
    }
  }
}

void Federate::finish() {
  {
    std::lock_guard lock(frame_mutex_);
    stopping_ = true;
  }
  tick_sub_->close();  // no step runs after this
  command_sub_->close();
  std::string reason;
  {
    std::lock_guard lock(command_mutex_);
    reason = stop_reason_;
  }
  if (stop_handler_) {
    try {
      stop_handler_();
    } catch (const std::exception& e) {
      log_->error("stop handler failed: {}", e.what());
      exit_code_.store(1);
    }
  }
  const auto stats = statistics();
  log_->info("stopping reason=\"{}\" frames={} overruns={} compute_p50_us={:.1f} "
             "compute_p99_us={:.1f} compute_max_us={:.1f} late_inputs={}",
             reason, stats.frames, stats.overruns, stats.compute.percentile_us(50),
             stats.compute.percentile_us(99), stats.compute.max_us(), stats.late_inputs);
  publish_status(exit_code_.load() == 0 ? msg::FEDERATE_STOPPING : msg::FEDERATE_FAILED, reason);
  // No lost samples: every reliable writer waits until its readers acknowledged.
  for (auto& flush : flushers_) flush();
  frame_done_pub_->wait_for_acknowledgments(std::chrono::seconds(1));
  status_pub_->wait_for_acknowledgments(std::chrono::seconds(1));
}

}  // namespace fedsim::runtime
