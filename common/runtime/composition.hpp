// The in-process host: several components in one process, wired by their declared ports, with
// the frame order of a lockstep federation and no DDS. Frame N of every component reads what
// was written in frame N-1 (the newest sample of the topic, as a DDS reader's latest_before(N)
// gives it) and its writes become visible at frame N+1, so a scenario composed in-process and
// flown as a DDS lockstep federation computes the same numbers. Ticks come from the same run
// control as fedsim-timing's (common/frame_clock) and are built as its ticks are
// (frame_tick.hpp); commands are delivered before the step of the next frame, as the runtime
// delivers them. The composition is its own frame clock: a Driver cannot be added.
//
// Uses: closed-loop tests, Monte Carlo runs, the batch program fedsim-fly, `fedsim run
// --in-process`. Components step in the order added; the order cannot change a result.
#pragma once

#include "common/frame_clock/run_control.hpp"
#include "common/runtime/component.hpp"

#include <functional>
#include <map>
#include <memory>
#include <string>
#include <vector>

namespace fedsim::runtime {

class Composition final : private PortBinder {
 public:
  struct Options {
    double rate_hz = 50.0;     // frame rate [Hz]
    bool start_frozen = false;  // first frame in FREEZE instead of RUN
  };

  explicit Composition(Options options);
  ~Composition() override;
  Composition(const Composition&) = delete;
  Composition& operator=(const Composition&) = delete;

  /// Adds a component (not owned; it must outlive the composition): starts it
  /// (Component::on_start, which may throw: then it is not added) and binds its ports.
  void add(Component& component);
  /// Calls `tap` with every sample written on `topic`, in the order written (recorders).
  template <class T>
  void on_written(const Topic<T>& topic, std::function<void(const T&)> tap) {
    channel<T>(topic.info).taps.push_back(std::move(tap));
  }
  /// Queues an instructor command: RUN/FREEZE/RESET go to the frame clock, every command to
  /// every component's on_command before its next step (SHUTDOWN stops the run).
  void command(const msg::SimCommand& command);

  /// Runs one frame and returns its context.
  const FrameContext& step_frame();
  /// Runs `frames` frames (fewer if a SHUTDOWN command arrives); returns the frames run.
  /// `progress` (optional) is called after each frame.
  std::uint64_t run(std::uint64_t frames,
                    const std::function<void(const FrameContext&)>& progress = {});
  /// Calls every component's on_stop once (also done by the destructor if not called).
  void stop();

  bool shutdown_requested() const { return shutdown_; }
  const FrameContext& last_frame() const { return context_; }
  /// Total faults the components reported.
  std::uint64_t fault_count() const;
  /// Topics written by some component and read by none, read by some (not only monitored)
  /// and written by none, and only monitored and written by none.
  std::vector<std::string> unread_topics() const;
  std::vector<std::string> unwritten_topics() const;
  std::vector<std::string> unwritten_monitored_topics() const;

 private:
  struct ChannelBase {
    virtual ~ChannelBase() = default;
    virtual void end_frame() = 0;
    const TopicInfo* topic = nullptr;
    int writers = 0;
    int readers = 0;   // every reader, monitors included
    int monitors = 0;  // of which monitors (optional: never missed)
  };
  template <class T>
  struct Channel final : ChannelBase {
    std::vector<T> previous;  // written in the last frame: what this frame reads
    std::vector<T> current;   // written in this frame
    std::vector<std::function<void(const T&)>> taps;
    std::vector<std::function<void(const T&)>> arrivals;  // Input::on_arrival of its readers
    void end_frame() override {
      previous.swap(current);
      current.clear();
      for (const T& sample : previous) {
        for (const auto& arrive : arrivals) arrive(sample);
      }
    }
  };

  template <class T>
  Channel<T>& channel(const TopicInfo& topic) {
    auto& slot = channels_[topic.name];
    if (!slot) {
      auto c = std::make_unique<Channel<T>>();
      c->topic = &topic;
      slot = std::move(c);
    }
    auto* typed = dynamic_cast<Channel<T>*>(slot.get());
    if (!typed) throw std::logic_error("topic " + topic.name + " bound with two types");
    return *typed;
  }
  template <class T>
  void bind_input(Input<T>& port) {
    Channel<T>& c = channel<T>(*port.info().topic);
    ++c.readers;
    if (port.info().monitor) ++c.monitors;
    port.set_writer_count([&c] { return c.writers; });
    if (port.arrival()) {
      c.arrivals.push_back([&port](const T& sample) {
        if (!port.acceptor() || port.acceptor()(sample)) port.arrival()(sample, WriterId{});
      });
    }
    bound_->refreshers.push_back([&c, &port] {
      // The last sample of the previous frame the port accepts (Input::accept_only).
      for (auto it = c.previous.rbegin(); it != c.previous.rend(); ++it) {
        if (port.acceptor() && !port.acceptor()(*it)) continue;
        port.slot() = *it;
        port.mark_updated();
        return;
      }
    });
  }
  template <class T>
  void bind_output(Output<T>& port) {
    Channel<T>& c = channel<T>(*port.info().topic);
    ++c.writers;
    port.set_sink([&c](const T& sample) {
      c.current.push_back(sample);
      for (const auto& tap : c.taps) tap(sample);
      return true;
    });
  }

#define FEDSIM_BIND_IN_PROCESS(Msg)                                \
  void bind(Input<msg::Msg>& port) override { bind_input(port); } \
  void bind(Output<msg::Msg>& port) override { bind_output(port); }
  FEDSIM_PORT_MESSAGE_TYPES(FEDSIM_BIND_IN_PROCESS)
#undef FEDSIM_BIND_IN_PROCESS

  struct Member {
    Component* component = nullptr;
    std::vector<std::function<void()>> refreshers;
  };

  Options options_;
  double period_s_;
  timing::RunControl clock_;
  std::vector<Member> members_;
  Member* bound_ = nullptr;  // the member whose ports are being bound
  std::map<std::string, std::unique_ptr<ChannelBase>> channels_;
  std::vector<msg::SimCommand> commands_;
  std::vector<msg::SimCommand> commands_now_;
  FrameContext context_;
  bool shutdown_ = false;
  bool stopped_ = false;
};

}  // namespace fedsim::runtime
