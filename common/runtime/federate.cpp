#include "common/runtime/federate.hpp"

#include "common/runtime/command_settings.hpp"
#include "common/runtime/frame_tick.hpp"
#include "common/runtime/log.hpp"
#include "common/runtime/shutdown.hpp"
#include "common/frame_clock/silence_watch.hpp"
#include "common/util/monotonic_clock.hpp"

#include <unistd.h>

#include <algorithm>

namespace fedsim::runtime {

namespace {
constexpr auto kStatusPeriod = std::chrono::seconds(1);
constexpr auto kInputJoinTimeout = std::chrono::seconds(3);
// The frame thread wakes at least this often to check signals, deadlines and the status period.
constexpr auto kLoopWakeup = std::chrono::milliseconds(20);

std::string host_name() {
  char buf[256] = {};
  gethostname(buf, sizeof(buf) - 1);
  return buf;
}

WriterId writer_id(const eprosima::fastrtps::rtps::InstanceHandle_t& handle) {
  WriterId id{};
  for (std::size_t i = 0; i < id.size(); ++i) id[i] = handle.value[i];
  return id;
}

/// A step function as a component without ports (tools).
class FunctionComponent final : public Component {
 public:
  FunctionComponent(std::string name, Federate::StepFunction step,
                    Federate::CommandHandler on_command, std::function<void()> on_stop)
      : Component(std::move(name)),
        step_(std::move(step)),
        command_(std::move(on_command)),
        stop_(std::move(on_stop)) {}
  void on_command(const msg::SimCommand& command) override {
    if (command_) command_(command);
  }
  void step(const FrameContext& frame) override { step_(frame); }
  void on_stop() override {
    if (stop_) stop_();
  }

 private:
  Federate::StepFunction step_;
  Federate::CommandHandler command_;
  std::function<void()> stop_;
};
}  // namespace

// ---- Ports over DDS ---------------------------------------------------------------------------

/// Binds a component's ports to readers and writers of the federate's participant. Inputs are
/// refreshed on the frame thread before each step: lockstep inputs (and every stamped input)
/// with the newest sample of an earlier frame, the others with the newest sample.
class Federate::PortBindings final : public PortBinder {
 public:
  explicit PortBindings(Federate& federate) : federate_(federate) {}

  void refresh_inputs(const FrameContext& ctx) {
    first_sample_frames_ = timing::SilenceWatch::first_sample_frames_for(
        federate_.options().silent_frames, ctx.mode == msg::TIMING_MODE_REALTIME, ctx.frame_period_s);
    for (auto& refresh : refreshers_) refresh(ctx.frame);
  }

#define FEDSIM_BIND_OVER_DDS(Msg)                                  \
  void bind(Input<msg::Msg>& port) override { bind_input(port); } \
  void bind(Output<msg::Msg>& port) override { bind_output(port); }
  FEDSIM_PORT_MESSAGE_TYPES(FEDSIM_BIND_OVER_DDS)
#undef FEDSIM_BIND_OVER_DDS

 private:
  template <class T>
  void bind_input(Input<T>& port) {
    const Topic<T> topic{*port.info().topic};
    const bool lockstep = port.info().lockstep_input && Stamped<T>;
    typename Subscription<T>::SampleHandler on_sample;
    if (port.arrival()) {
      on_sample = [&arrival = port.arrival()](const T& sample, const fdds::SampleInfo& info) {
        arrival(sample, writer_id(info.publication_handle));
      };
    }
    Subscription<T>& sub = federate_.subscribe(topic, port.info().qos, lockstep, std::move(on_sample));
    port.set_writer_count([&sub] { return sub.matched_writers(); });
    if (port.acceptor()) sub.set_filter(port.acceptor());
    if (port.writer_lost()) {
      sub.set_liveliness_handler([&lost = port.writer_lost()](const fdds::LivelinessChangedStatus& status) {
        if (status.not_alive_count_change > 0) lost(writer_id(status.last_publication_handle));
      });
    }
    if constexpr (Stamped<T>) {
      refreshers_.push_back([&sub, &port, last = std::int64_t{-1}](std::uint64_t frame) mutable {
        if (!sub.latest_before(frame, port.slot())) return false;
        const auto stamp = static_cast<std::int64_t>(port.slot().stamp().frame());
        if (stamp == last) return false;
        last = stamp;
        port.mark_updated();
        return true;
      });
    } else {
      refreshers_.push_back([&sub, &port, seen = std::uint64_t{0}](std::uint64_t) mutable {
        const std::uint64_t received = sub.received_count();
        if (received == seen || !sub.latest(port.slot())) return false;
        seen = received;
        port.mark_updated();
        return true;
      });
    }
    if (port.info().topic->every_frame) watch_for_silence(sub, refreshers_.back(), lockstep_input_of(sub.topic_name()));
  }

  /// Wraps a port's refresh with a frame-counted silence watch (no DDS deadline: see
  /// common/frame_clock/silence_watch.hpp): a matched writer that wrote nothing for
  /// --silent-frames frames is a fault of kind silent_writer, named by topic.
  template <class T>
  void watch_for_silence(Subscription<T>& sub, std::function<bool(std::uint64_t)>& refresh,
                         std::shared_ptr<LockstepInput> lockstep) {
    const std::uint64_t limit = federate_.options().silent_frames;
    if (limit == 0) return;
    refresh = [&sub, inner = std::move(refresh), watch = timing::SilenceWatch(limit),
               component = federate_.component_, log = federate_.log_, lockstep,
               &first_sample_frames = first_sample_frames_](std::uint64_t frame) mutable {
      const bool updated = inner(frame);
      watch.set_first_sample_frames(first_sample_frames);
      const auto event = watch.observe(frame, sub.matched_writers() > 0, updated);
      if (lockstep) lockstep->silent.store(watch.silent());
      switch (event) {
        case timing::SilenceWatch::Event::kSilent:
          component->report_port_fault(
              "silent_writer", sub.topic_name() + ": a matched writer wrote nothing for " +
                                   std::to_string(watch.quiet_frames()) +
                                   " frames (frames no longer wait for it until it writes again)");
          break;
        case timing::SilenceWatch::Event::kResumed:
          log->warn("frame={} topic={}: its writer writes again", frame, sub.topic_name());
          break;
        case timing::SilenceWatch::Event::kNone:
          break;
      }
      return updated;
    };
  }

  template <class T>
  void bind_output(Output<T>& port) {
    Publisher<T>& pub = federate_.publish(Topic<T>{*port.info().topic}, port.info().qos);
    port.set_sink([&pub](const T& sample) { return pub.publish(sample); });
    port.set_reader_count([&pub] { return pub.matched_readers(); });
  }

  /// The lockstep input registered for a topic (nullptr if it is not one).
  std::shared_ptr<LockstepInput> lockstep_input_of(const std::string& topic) const {
    std::lock_guard lock(federate_.frame_mutex_);
    for (const auto& in : federate_.inputs_) {
      if (in->topic == topic) return in;
    }
    return nullptr;
  }

  Federate& federate_;
  std::vector<std::function<bool(std::uint64_t)>> refreshers_;  // true: a new sample
  std::uint64_t first_sample_frames_ = 0;  // this frame's first-sample limit of the silence watches
};

// ---- Federate ---------------------------------------------------------------------------------

Federate::Federate(const FederateOptions& options) : options_(options) {
  install_shutdown_handler();
  log_ = make_logger(options_.name, options_.log_level);
  start_ns_ = util::monotonic_ns();
  options_.dds.name = options_.name;
  dds_ = DdsParticipant::create(options_.dds);
  done_sample_.federate(options_.name);
  status_pub_ = std::make_unique<Publisher<msg::FederateStatus>>(dds_, topics::federate_status);
  command_sub_ = std::make_unique<Subscription<msg::SimCommand>>(
      dds_, topics::sim_command, qos::kCommand,
      // A setting comes twice, the original and the command holder's copy (command_settings.hpp):
      // it is applied once. Deliveries of one reader are serialised: no lock for the filter.
      [this, redelivery = RedeliveryFilter()](const msg::SimCommand& cmd, const auto&) mutable {
        if (redelivery.first_delivery(cmd)) handle_command(cmd);
      });
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

double Federate::input_timeout_s(const msg::FrameTick& tick) const {
  const double period = tick.frame_period_s();
  if (tick.mode() == msg::TIMING_MODE_REALTIME && period > 0.0) {
    return std::min(options_.input_timeout_s, 0.5 * period);
  }
  return options_.input_timeout_s;
}

std::shared_ptr<Federate::LockstepInput> Federate::register_lockstep_input(
    const std::string& topic, std::function<int()> matched_writers) {
  auto input = std::make_shared<LockstepInput>();
  input->topic = topic;
  input->matched_writers = std::move(matched_writers);
  std::lock_guard lock(frame_mutex_);
  inputs_.push_back(input);
  return input;
}

std::function<void(std::uint64_t)> Federate::add_lockstep_input(
    const std::string& topic, std::function<int()> matched_writers) {
  auto input = register_lockstep_input(topic, std::move(matched_writers));
  return [this, input](std::uint64_t frame) { on_lockstep_input(*input, frame); };
}

void Federate::LockstepInput::record_locked(std::int64_t frame) {
  recent_frames[recent_next] = frame;
  recent_next = (recent_next + 1) % recent_frames.size();
}

std::int64_t Federate::LockstepInput::newest_locked() const {
  return *std::max_element(recent_frames.begin(), recent_frames.end());
}

bool Federate::LockstepInput::has_locked(std::int64_t frame) const {
  return std::find(recent_frames.begin(), recent_frames.end(), frame) != recent_frames.end();
}

void Federate::handle_command(const msg::SimCommand& command) {
  if (command.kind() == msg::COMMAND_SHUTDOWN) {
    stop("shutdown command from " + command.issuer().to_string());
    return;
  }
  if (driving_.load()) return;
  std::lock_guard lock(command_mutex_);
  commands_.push_back(command);
}

// Listener thread: record the tick and wake the frame thread.
void Federate::handle_tick(const msg::FrameTick& tick) {
  std::unique_lock lock(frame_mutex_);
  if (!accepting_ticks_ || stopping_) return;
  if (stepping_ && tick.frame() == stepping_frame_) return;  // acknowledged when it finishes
  if (stepped_any_ && tick.frame() <= last_frame_) {
    // The timing federate repeats a tick when an acknowledgement went missing: re-acknowledge.
    ++stats_.repeated_ticks;
    if (tick.frame() == last_frame_) {
      const float compute_us = last_compute_us_;
      const std::uint64_t latency_ns = last_latency_ns_;
      lock.unlock();
      publish_done(tick.frame(), compute_us, latency_ns);
    }
    return;
  }
  if (pending_ && pending_tick_.frame() == tick.frame()) return;  // a repeat of the pending tick
  // A newer tick replacing a pending one (realtime) keeps the time the wait for inputs began:
  // otherwise a federate whose input stays missing would restart its wait on every tick and
  // never step.
  if (pending_) {
    ++stats_.skipped_ticks;
  } else {
    pending_since_ns_ = util::monotonic_ns();
  }
  pending_tick_ = tick;
  pending_ = true;
  last_tick_arrival_ns_ = util::monotonic_ns();
  const bool ready = inputs_ready_locked(tick);
  lock.unlock();
  if (ready) frame_bell_.ring();
}

// Listener thread: a lockstep input's sample of `frame` arrived.
void Federate::on_lockstep_input(LockstepInput& input, std::uint64_t frame) {
  bool wake = false;
  {
    std::lock_guard lock(frame_mutex_);
    input.record_locked(static_cast<std::int64_t>(frame));
    wake = pending_ && !stopping_ && inputs_ready_locked(pending_tick_);
  }
  if (wake) frame_bell_.ring();
}

// In lockstep, frame N needs the sample stamped N-1, or a newer one with nothing missing before
// it (a writer may write nothing in a frame: nav before its first aircraft state). "Any sample
// of N-1 or later" is not enough: a writer that has stepped frame N already may have delivered
// N while N-1 was lost, and the step would read N-2's sample (Subscription::latest_before)
// without counting a late input (found by tests/hosts with 5% loss between namespaces). In
// realtime a writer may skip frames (skipped ticks), so a newer sample is accepted as before.
bool Federate::input_ready_locked(const LockstepInput& in, const msg::FrameTick& tick) const {
  const auto needed = static_cast<std::int64_t>(tick.frame()) - 1;
  if (needed < 0 || in.matched_writers() == 0 || in.silent.load()) return true;
  if (tick.mode() != msg::TIMING_MODE_LOCKSTEP) return in.newest_locked() >= needed;
  if (in.has_locked(needed)) return true;
  return in.newest_locked() > needed && !(in.missing_samples && in.missing_samples());
}

bool Federate::inputs_ready_locked(const msg::FrameTick& tick) const {
  return std::all_of(inputs_.begin(), inputs_.end(),
                     [&](const auto& in) { return input_ready_locked(*in, tick); });
}

void Federate::log_late_inputs_locked(const msg::FrameTick& tick) const {
  for (const auto& in : inputs_) {
    if (!input_ready_locked(*in, tick)) {
      log_->warn("frame={} input={} missing after {:.3f}s: stepping with its last sample",
                 tick.frame(), in->topic, input_timeout_s(tick));
    }
  }
}

// Frame thread: a lockstep input read best effort gets a reliable reader as soon as a reliable
// writer of its topic is known (federate.hpp).
void Federate::read_inputs_reliably() {
  std::vector<std::shared_ptr<LockstepInput>> inputs;
  {
    std::lock_guard lock(frame_mutex_);
    inputs = inputs_;
  }
  for (const auto& in : inputs) {
    if (in->read_reliably) in->read_reliably();
  }
}

// Frame thread: refresh the inputs, deliver the commands, step, acknowledge.
void Federate::run_frame(const msg::FrameTick& tick, bool late) {
  const FrameContext ctx = context_of(tick);
  {
    std::lock_guard lock(command_mutex_);
    commands_now_.swap(commands_);
    commands_.clear();
  }
  const std::uint64_t start_ns = util::monotonic_ns();
  const std::uint64_t latency_ns =
      start_ns > tick.publish_time_ns() ? start_ns - tick.publish_time_ns() : 0;
  const std::uint64_t faults_before = component_->fault_count();
  try {
    bindings_->refresh_inputs(ctx);
    for (const auto& cmd : commands_now_) component_->on_command(cmd);
    component_->step(ctx);
  } catch (const std::exception& e) {
    log_->error("frame={} step failed: {}", ctx.frame, e.what());
    fail(std::string("step failed: ") + e.what());
    std::lock_guard lock(frame_mutex_);
    stepping_ = false;
    stopping_ = true;
    return;
  }
  const std::uint64_t compute_ns = util::monotonic_ns() - start_ns;
  const float compute_us = static_cast<float>(compute_ns / 1000.0);
  bool frame_limit = false;
  {
    std::lock_guard lock(frame_mutex_);
    stats_.compute.add_ns(compute_ns);
    stats_.tick_latency.add_ns(latency_ns);
    window_compute_.add_ns(compute_ns);
    ++stats_.frames;
    if (late) ++stats_.late_inputs;
    if (ctx.frame_period_s > 0 && compute_ns > ctx.frame_period_s * 1e9) ++stats_.overruns;
    stepped_any_ = true;
    stepping_ = false;
    last_frame_ = ctx.frame;
    last_stepped_ = ctx;
    last_compute_us_ = compute_us;
    last_latency_ns_ = latency_ns;
    frame_limit = options_.max_frames != 0 && stats_.frames >= options_.max_frames;
  }
  publish_done(ctx.frame, compute_us, latency_ns);
  if (component_->fault_count() != faults_before) {
    publish_status(msg::FEDERATE_RUNNING, "fault: " + component_->faults().back().last);
  }
  if (frame_limit) stop("stepped " + std::to_string(options_.max_frames) + " frames");
}

void Federate::publish_done(std::uint64_t frame, float compute_us, std::uint64_t latency_ns) {
  std::lock_guard lock(done_mutex_);
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
    status.late_inputs(stats_.late_inputs);
    status.compute_mean_us(static_cast<float>(window_compute_.mean_us()));
    status.compute_max_us(static_cast<float>(window_compute_.max_us()));
    window_compute_.reset();
  }
  status.faults(component_ ? component_->fault_count() : 0);
  status.uptime_s((util::monotonic_ns() - start_ns_) * 1e-9);
  status_pub_->publish(status);
}

void Federate::stop(const std::string& reason) {
  if (!stop_requested_.exchange(true)) {
    std::lock_guard lock(command_mutex_);  // not frame_mutex_: stop() may be called from a step
    stop_reason_ = reason;
  }
  frame_bell_.ring();
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
  // The repair path before the first tick where the writers are already known (later ones are
  // picked up by the frame loop).
  read_inputs_reliably();
  for (const auto& in : inputs) {
    while (in->reliable_reader_unmatched && in->reliable_reader_unmatched() &&
           std::chrono::steady_clock::now() < until && !shutdown_requested()) {
      std::this_thread::sleep_for(std::chrono::milliseconds(10));
    }
  }
}

int Federate::run(StepFunction step) {
  FunctionComponent component(options_.name, std::move(step), command_handler_, stop_handler_);
  return run(component);
}

// The tick reader and the acknowledgement writer: a component's, not a driver's.
void Federate::follow_ticks() {
  const std::string sync = options_.sync_qos_suffix;
  frame_done_pub_ = std::make_unique<Publisher<msg::FrameDone>>(
      dds_, topics::frame_done, topics::frame_done.info.default_qos + sync);
  tick_sub_ = std::make_unique<Subscription<msg::FrameTick>>(
      dds_, topics::frame_tick, topics::frame_tick.info.default_qos + sync,
      [this](const msg::FrameTick& tick, const auto&) { handle_tick(tick); });
}

int Federate::run(Component& component) {
  component_ = &component;
  component.set_logger(log_);
  component.on_start(HostServices{dds_});
  auto* driver = dynamic_cast<Driver*>(&component);
  driving_.store(driver != nullptr);
  if (!driver) follow_ticks();
  bindings_ = std::make_unique<PortBindings>(*this);
  for (const auto& port : component.ports()) port->bind(*bindings_);
  if (driver) {
    driver->set_waker([this] { frame_bell_.ring(); });
    publish_status(msg::FEDERATE_READY, "");
    log_->info("ready ports={} (driving the frames)", component.ports().size());
    drive_loop(*driver);
  } else {
    wait_for_inputs_to_match();
    {
      std::lock_guard lock(frame_mutex_);
      accepting_ticks_ = true;
    }
    publish_status(msg::FEDERATE_READY, "");
    log_->info("ready ports={}", component.ports().size());
    frame_loop();
  }
  finish();
  return exit_code_.load();
}

void Federate::publish_driver_notes(Driver& driver) {
  const Driver::Progress progress = driver.progress();
  {
    std::lock_guard lock(frame_mutex_);
    stats_.frames = progress.frames;
    stats_.overruns = progress.overruns;
  }
  for (const auto& line : driver.take_notes()) publish_status(msg::FEDERATE_RUNNING, line);
}

// Frame thread: SIGINT/SIGTERM stop the loop.
bool Federate::stopped_by_signal() {
  if (!shutdown_requested()) return false;
  stop(shutdown_signal() ? "signal " + std::to_string(shutdown_signal()) : "shutdown");
  return true;
}

// The frame thread of a driver: drive() when it asked to be, or when it rang; the status as for
// every federate (RUNNING once it makes frames, then once a second with its frame count).
void Federate::drive_loop(Driver& driver) {
  auto next_status = std::chrono::steady_clock::now() + kStatusPeriod;
  bool announced_running = false;
  while (!stop_requested_.load()) {
    if (stopped_by_signal()) break;
    const std::uint32_t rang = frame_bell_.value();  // before driving: no wake-up is lost
    std::optional<std::uint64_t> next;
    try {
      next = driver.drive(util::monotonic_ns());
    } catch (const std::exception& e) {
      log_->error("drive failed: {}", e.what());
      fail(std::string("drive failed: ") + e.what());
      break;
    }
    if (!announced_running && driver.progress().running) {
      announced_running = true;
      publish_status(msg::FEDERATE_RUNNING, "");
    }
    publish_driver_notes(driver);
    if (!next) {
      if (driver.exit_code() != 0) exit_code_.store(driver.exit_code());
      stop(driver.failure().empty() ? "done" : driver.failure());
      break;
    }
    if (std::chrono::steady_clock::now() >= next_status) {
      next_status += kStatusPeriod;
      publish_status(announced_running ? msg::FEDERATE_RUNNING : msg::FEDERATE_READY, "");
    }
    const std::uint64_t now = util::monotonic_ns();
    if (*next > now) {
      const auto until_status = std::chrono::duration_cast<std::chrono::nanoseconds>(
          next_status - std::chrono::steady_clock::now());
      frame_bell_.wait(rang, std::max(std::chrono::nanoseconds(0),
                                      std::min(std::chrono::nanoseconds(*next - now), until_status)));
    }
  }
  publish_driver_notes(driver);
}

// Frame thread, between frames: the tick watchdog (Component::tick_watchdog_periods). Returns
// how long the loop may sleep before the watch must look again.
std::chrono::nanoseconds Federate::watch_ticks() {
  const double periods = component_->tick_watchdog_periods();
  if (!(periods > 0.0)) return kLoopWakeup;
  FrameContext last;
  std::uint64_t arrival_ns = 0;
  {
    std::lock_guard lock(frame_mutex_);
    if (!stepped_any_ || pending_ || stepping_ || stopping_) return kLoopWakeup;
    last = last_stepped_;
    arrival_ns = last_tick_arrival_ns_;
  }
  if (last.mode != msg::TIMING_MODE_REALTIME || !(last.frame_period_s > 0.0)) return kLoopWakeup;
  const double silent_s = static_cast<double>(util::monotonic_ns() - arrival_ns) * 1e-9;
  const double limit_s = periods * last.frame_period_s;
  if (silent_s < limit_s) {
    return std::chrono::nanoseconds(static_cast<std::int64_t>((limit_s - silent_s) * 1e9) + 1);
  }
  try {
    component_->on_ticks_stopped(last, silent_s);
  } catch (const std::exception& e) {
    log_->error("the tick watchdog's handler failed: {}", e.what());
    fail(std::string("tick watchdog handler failed: ") + e.what());
  }
  return kLoopWakeup;
}

void Federate::frame_loop() {
  const std::uint64_t deadline_ns =
      options_.duration_s > 0 ? start_ns_ + static_cast<std::uint64_t>(options_.duration_s * 1e9)
                              : 0;
  auto next_status = std::chrono::steady_clock::now() + kStatusPeriod;
  bool announced_running = false;
  while (!stop_requested_.load()) {
    if (stopped_by_signal()) break;
    if (deadline_ns != 0 && util::monotonic_ns() >= deadline_ns) {
      stop("duration of " + std::to_string(options_.duration_s) + " s reached");
      break;
    }
    msg::FrameTick tick;
    bool take = false;
    bool late = false;
    const std::uint32_t rang = frame_bell_.value();  // before looking: no wake-up is lost
    std::chrono::nanoseconds wait = std::min<std::chrono::nanoseconds>(kLoopWakeup, watch_ticks());
    {
      std::lock_guard lock(frame_mutex_);
      if (pending_ && !stopping_ && !stop_requested_.load()) {
        const bool ready = inputs_ready_locked(pending_tick_);
        const double waited_s = (util::monotonic_ns() - pending_since_ns_) * 1e-9;
        const double timeout_s = input_timeout_s(pending_tick_);
        // Waiting for an input: wake when its timeout runs out, not a loop period later.
        wait = std::min<std::chrono::nanoseconds>(
            wait, std::chrono::nanoseconds(static_cast<std::int64_t>(
                      std::max(0.0, timeout_s - waited_s) * 1e9) + 1));
        if (ready || waited_s >= timeout_s) {
          if (!ready) log_late_inputs_locked(pending_tick_);
          tick = pending_tick_;
          pending_ = false;
          stepping_ = true;
          stepping_frame_ = tick.frame();
          take = true;
          late = !ready;
        }
      }
    }
    if (take) {
      run_frame(tick, late);
    } else if (!stop_requested_.load()) {
      frame_bell_.wait(rang, wait);
    }
    if (!announced_running && stepped_any_) {
      announced_running = true;
      publish_status(msg::FEDERATE_RUNNING, "");
    }
    if (std::chrono::steady_clock::now() >= next_status) {
      next_status += kStatusPeriod;
      read_inputs_reliably();  // a reliable writer that appeared since
      // Between steps, on the frame thread: the component's note cannot race its step.
      publish_status(announced_running ? msg::FEDERATE_RUNNING : msg::FEDERATE_READY,
                     stepped_any_ ? component_->progress_note() : std::string());
    }
  }
}

void Federate::finish() {
  {
    std::lock_guard lock(frame_mutex_);
    stopping_ = true;
  }
  if (tick_sub_) tick_sub_->close();  // no tick is taken after this
  command_sub_->close();
  std::string reason;
  {
    std::lock_guard lock(command_mutex_);
    reason = stop_reason_;
  }
  try {
    component_->on_stop();
  } catch (const std::exception& e) {
    log_->error("stop handler failed: {}", e.what());
    exit_code_.store(1);
  }
  std::string faults;
  for (const auto& f : component_->faults()) {
    faults += (faults.empty() ? "" : ", ") + f.kind + "=" + std::to_string(f.count);
    log_->error("fault summary kind={} count={} last=\"{}\"", f.kind, f.count, f.last);
  }
  if (!faults.empty()) {
    exit_code_.store(1);
    reason += (reason.empty() ? "" : "; ") + std::string("faults: ") + faults;
  }
  const auto stats = statistics();
  log_->info("stopping reason=\"{}\" frames={} overruns={} compute_p50_us={:.1f} "
             "compute_p99_us={:.1f} compute_max_us={:.1f} late_inputs={} faults={}",
             reason, stats.frames, stats.overruns, stats.compute.percentile_us(50),
             stats.compute.percentile_us(99), stats.compute.max_us(), stats.late_inputs,
             component_->fault_count());
  publish_status(exit_code_.load() == 0 ? msg::FEDERATE_STOPPING : msg::FEDERATE_FAILED, reason);
  // No lost samples: every reliable writer waits until its readers acknowledged.
  for (auto& flush : flushers_) flush();
  if (frame_done_pub_) frame_done_pub_->wait_for_acknowledgments(std::chrono::seconds(1));
  status_pub_->wait_for_acknowledgments(std::chrono::seconds(1));
}

}  // namespace fedsim::runtime
