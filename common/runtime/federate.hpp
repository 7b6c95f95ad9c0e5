// The DDS host of a component: one participant, a reader or writer on each of the component's
// ports, and the frame loop that steps the component once per tick and acknowledges it (or, for
// the frame clock, a runtime::Driver, the loop that drives it: see run()).
//
// Subscribes: fedsim/frame_tick (profile "tick"; not for a driver), fedsim/sim_command ("command").
// Publishes:  fedsim/frame_done ("frame_done") once per stepped frame (not for a driver),
//             fedsim/federate_status ("status") on every state change and once a second.
//
// Threads: DDS listener threads only record what arrived (the tick, each lockstep input's
// frame, commands) and wake the frame thread - the thread that called run() - which refreshes
// the inputs, delivers commands, runs the step and publishes the acknowledgement. No step runs
// on a middleware thread and no lock is held while a step runs.
//
// Lockstep inputs: a read port on a lockstep-input topic must deliver the sample of frame N-1
// before frame N steps (when a writer is matched), which makes a lockstep run reproducible:
// every federate sees exactly the previous frame's data, whatever the thread timing and losses.
// In lockstep the sample stamped N-1 itself must have arrived, or a newer one with none of the
// writer's samples missing before it (a writer that wrote nothing in frame N-1); a newer one
// does not stand in for a lost one. In realtime any sample of frame N-1 or later will do. A
// port read best effort whose writer is reliable also gets a reliable reader
// (Subscription::read_reliably_too), so a sample lost on the network is repaired rather than
// missed. A missing input is waited for at most --input-timeout (half a
// frame in realtime), then the frame steps with the last sample and the late input is counted
// and logged.
#pragma once

#include "common/runtime/component.hpp"
#include "common/runtime/dds_participant.hpp"
#include "common/runtime/federate_options.hpp"
#include "common/runtime/publisher.hpp"
#include "common/runtime/subscription.hpp"
#include "common/util/doorbell.hpp"
#include "common/util/latency_stats.hpp"

#include <spdlog/logger.h>

#include <array>
#include <atomic>
#include <chrono>
#include <cstdint>
#include <functional>
#include <memory>
#include <mutex>
#include <string>
#include <vector>

namespace fedsim::runtime {

/// Per-federate frame statistics (compute time of the step, overruns).
struct FrameStatistics {
  std::uint64_t frames = 0;
  std::uint64_t overruns = 0;           // step took longer than the frame period
  std::uint64_t repeated_ticks = 0;     // a tick seen twice (the acknowledgement was re-sent)
  std::uint64_t skipped_ticks = 0;      // realtime: ticks that arrived while one was pending
  std::uint64_t late_inputs = 0;        // frames stepped without a lockstep input
  util::LatencyStats compute;           // step compute time
  util::LatencyStats tick_latency;      // tick publish -> step start
};

class Federate {
 public:
  using StepFunction = std::function<void(const FrameContext&)>;
  using CommandHandler = std::function<void(const msg::SimCommand&)>;

  explicit Federate(const FederateOptions& options);
  ~Federate();
  Federate(const Federate&) = delete;
  Federate& operator=(const Federate&) = delete;

  const std::string& name() const { return options_.name; }
  const FederateOptions& options() const { return options_; }
  spdlog::logger& log() const { return *log_; }
  const std::shared_ptr<DdsParticipant>& dds() const { return dds_; }

  /// Runs `component` (its ports bound to DDS readers and writers) until SIGINT/SIGTERM, a
  /// SHUTDOWN command, --duration or --frames. Returns the process exit code: 0 clean stop,
  /// 1 the step failed or the component reported faults. A Driver (component.hpp) is driven
  /// on this thread instead: no tick is read and no frame acknowledged; its run ends when
  /// drive() says so (its exit code then), on a signal or on a SHUTDOWN command.
  int run(Component& component);
  /// Runs a bare step function (tools whose readers are not ports, e.g. the recorder).
  int run(StepFunction step);

  /// For tools with dynamic-type readers: registers a lockstep input the runtime did not
  /// create. Call the returned function with the frame of every sample received.
  std::function<void(std::uint64_t)> add_lockstep_input(const std::string& topic,
                                                        std::function<int()> matched_writers);
  /// A writer / reader not bound to a port (tools and tests).
  template <class T>
  Publisher<T>& publish(const Topic<T>& topic, std::string_view qos = {}) {
    auto pub = std::make_shared<Publisher<T>>(dds_, topic, qos);
    endpoints_.push_back(pub);
    flushers_.push_back([p = pub.get()] { p->wait_for_acknowledgments(std::chrono::seconds(1)); });
    return *pub;
  }
  /// `on_sample` (optional) is called with every sample, on a middleware thread.
  template <class T>
  Subscription<T>& subscribe(const Topic<T>& topic, std::string_view qos = {},
                             bool lockstep_input = false,
                             typename Subscription<T>::SampleHandler on_sample = {});

  /// Commands (other than SHUTDOWN, which the runtime handles) are delivered on the frame
  /// thread just before the step (run(StepFunction) only; a component has on_command).
  void on_command(CommandHandler handler) { command_handler_ = std::move(handler); }
  /// Called once when the federate stops, after the last step (run(StepFunction) only).
  void on_stop(std::function<void()> handler) { stop_handler_ = std::move(handler); }

  /// Asks the loop to stop after the current frame (thread-safe).
  void stop(const std::string& reason);
  /// Marks the federate failed (exit code 1) and stops it.
  void fail(const std::string& reason);

  FrameStatistics statistics() const;

 private:
  struct LockstepInput {
    std::string topic;
    std::function<int()> matched_writers;
    // Adds a reliable reader where the topic's writer is reliable (nullptr: a tool's own reader),
    // and tells whether such a reader was added but has not matched yet.
    std::function<void()> read_reliably;
    std::function<bool()> reliable_reader_unmatched;
    // True while one of its writer's samples is known lost and not yet repaired (nullptr: never
    // known; a tool's reader of a reliable writer gets every sample in order).
    std::function<bool()> missing_samples;
    // The frames of the samples received lately, newest last (guarded by frame_mutex_).
    std::array<std::int64_t, 8> recent_frames{-1, -1, -1, -1, -1, -1, -1, -1};
    std::size_t recent_next = 0;
    void record_locked(std::int64_t frame);
    bool has_locked(std::int64_t frame) const;
    std::int64_t newest_locked() const;  // of the recent ones (an absurd stamp does not stick)
    // Its matched writer is silent (the port's silence watch): frames stop waiting for it until
    // it writes again, so a silent writer costs --silent-frames late frames, not every frame.
    std::atomic<bool> silent{false};
  };
  class PortBindings;

  std::shared_ptr<LockstepInput> register_lockstep_input(const std::string& topic,
                                                         std::function<int()> matched_writers);
  void handle_tick(const msg::FrameTick& tick);
  void handle_command(const msg::SimCommand& command);
  void on_lockstep_input(LockstepInput& input, std::uint64_t frame);
  bool input_ready_locked(const LockstepInput& input, const msg::FrameTick& tick) const;
  bool inputs_ready_locked(const msg::FrameTick& tick) const;
  void log_late_inputs_locked(const msg::FrameTick& tick) const;
  void read_inputs_reliably();
  void run_frame(const msg::FrameTick& tick, bool late);
  void publish_done(std::uint64_t frame, float compute_us, std::uint64_t latency_ns);
  void publish_status(msg::FederateState state, const std::string& message);
  void wait_for_inputs_to_match();
  void follow_ticks();
  void frame_loop();
  void drive_loop(Driver& driver);
  bool stopped_by_signal();
  void publish_driver_notes(Driver& driver);
  std::chrono::nanoseconds watch_ticks();
  void finish();
  double input_timeout_s(const msg::FrameTick& tick) const;

  FederateOptions options_;
  std::shared_ptr<spdlog::logger> log_;
  std::shared_ptr<DdsParticipant> dds_;
  std::vector<std::shared_ptr<void>> endpoints_;   // user publishers/subscriptions
  std::vector<std::function<void()>> flushers_;    // wait for acknowledgements at stop

  std::unique_ptr<Publisher<msg::FederateStatus>> status_pub_;
  // A component's, created by run() (a driver has neither: it writes the ticks).
  std::unique_ptr<Publisher<msg::FrameDone>> frame_done_pub_;
  std::unique_ptr<Subscription<msg::FrameTick>> tick_sub_;
  std::unique_ptr<Subscription<msg::SimCommand>> command_sub_;

  Component* component_ = nullptr;
  std::unique_ptr<PortBindings> bindings_;
  StepFunction step_;
  CommandHandler command_handler_;
  std::function<void()> stop_handler_;

  // Frame state shared with the listener threads, guarded by frame_mutex_. The step itself
  // runs without it.
  mutable std::mutex frame_mutex_;
  util::Doorbell frame_bell_;  // rung by the listeners: a tick, an input, a stop
  std::vector<std::shared_ptr<LockstepInput>> inputs_;
  bool accepting_ticks_ = false;
  bool stopping_ = false;
  bool pending_ = false;                // a tick waits to be stepped
  msg::FrameTick pending_tick_;
  std::uint64_t pending_since_ns_ = 0;
  bool stepping_ = false;               // the frame thread is inside run_frame
  std::uint64_t stepping_frame_ = 0;
  bool stepped_any_ = false;
  std::uint64_t last_tick_arrival_ns_ = 0;  // monotonic time the latest new tick arrived
  FrameContext last_stepped_;               // the context of the last frame stepped
  std::uint64_t last_frame_ = 0;        // last frame acknowledged
  float last_compute_us_ = 0.0f;
  std::uint64_t last_latency_ns_ = 0;
  FrameStatistics stats_;
  util::LatencyStats window_compute_;  // for the 1 s status report

  msg::FrameDone done_sample_;  // frame thread only
  std::mutex done_mutex_;       // done_sample_ is also re-sent from the tick listener

  std::mutex command_mutex_;
  std::vector<msg::SimCommand> commands_;       // received, not yet delivered
  std::vector<msg::SimCommand> commands_now_;   // delivered this frame (swapped: no allocation)

  std::atomic<bool> stop_requested_{false};
  std::atomic<bool> driving_{false};  // running a Driver: commands reach it on its own ports
  std::atomic<int> exit_code_{0};
  std::string stop_reason_;
  std::uint64_t start_ns_ = 0;
};

template <class T>
Subscription<T>& Federate::subscribe(const Topic<T>& topic, std::string_view qos,
                                     bool lockstep_input,
                                     typename Subscription<T>::SampleHandler on_sample) {
  if (!lockstep_input) {
    auto sub = std::make_shared<Subscription<T>>(dds_, topic, qos, std::move(on_sample));
    endpoints_.push_back(sub);
    return *sub;
  }
  if constexpr (Stamped<T>) {
    auto input = std::make_shared<LockstepInput>();
    input->topic = topic.name();
    auto sub = std::make_shared<Subscription<T>>(
        dds_, topic, qos,
        [this, in = input.get(), also = std::move(on_sample)](const T& sample, const auto& info) {
          on_lockstep_input(*in, sample.stamp().frame());
          if (also) also(sample, info);
        });
    input->matched_writers = [s = sub.get()] { return s->matched_writers(); };
    input->read_reliably = [s = sub.get(), dds = dds_.get()] {
      if (dds->has_reliable_writer(s->topic_name())) s->read_reliably_too(qos::kLockstepData);
    };
    input->missing_samples = [s = sub.get()] { return s->missing_samples(); };
    input->reliable_reader_unmatched = [s = sub.get()] {
      return s->has_reliable_reader() && !s->reads_reliably();
    };
    {
      std::lock_guard lock(frame_mutex_);
      inputs_.push_back(input);
    }
    endpoints_.push_back(sub);
    return *sub;
  } else {
    throw DdsError("topic " + topic.name() + " has no FrameStamp and cannot be a lockstep input");
  }
}

}  // namespace fedsim::runtime
