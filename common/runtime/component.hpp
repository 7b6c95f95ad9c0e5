// A federate's simulation side, independent of how it is hosted: the ports it reads and writes
// (declared once, at the top of its adapter), the commands it takes and the step it runs each
// frame. The same component runs
//   - as a DDS federate (runtime::Federate: one process, readers and writers on the ports), or
//   - in-process (runtime::Composition: several components in one process, no DDS, with the
//     frame order of a lockstep federation).
// Nothing here creates a DDS entity; hosts bind the ports (PortBinder).
//
// A Driver (below) is the one component that makes frames instead of stepping in them: the
// frame clock, fedsim-timing. The DDS host runs it on its own schedule in place of waiting for
// ticks; the in-process host plays that part itself (Composition).
//
// Frame rule (both hosts): in frame N an Input holds what was written in frame N-1 (lockstep
// inputs; in realtime over DDS, the newest sample) and an Output's samples are stamped N.
#pragma once

#include "common/runtime/topic_catalogue.hpp"

#include <spdlog/logger.h>

#include <array>
#include <cstdint>
#include <functional>
#include <memory>
#include <mutex>
#include <optional>
#include <string>
#include <vector>

namespace fedsim::runtime {

class DdsParticipant;

/// What a step needs to know about the frame it computes.
struct FrameContext {
  std::uint64_t frame = 0;       // tick number
  std::uint64_t sim_frame = 0;   // RUN frames since the last reset
  double sim_time_s = 0.0;       // simulation time at the start of the frame [s]
  double dt_s = 0.0;             // simulation step of this frame [s] (0 when frozen)
  double frame_period_s = 0.0;   // nominal frame period [s]
  msg::RunState run_state = msg::RUN_STATE_FREEZE;
  std::uint32_t reset_count = 0;
  msg::TimingMode mode = msg::TIMING_MODE_REALTIME;

  bool running() const { return run_state == msg::RUN_STATE_RUN; }
  bool resetting() const { return run_state == msg::RUN_STATE_RESET; }
  /// Simulation time at the end of the frame (the next frame's start time): after a RUN
  /// frame's step, (sim_frame + 1) * dt, computed as the timing federate computes sim time.
  double end_time_s() const {
    return running() ? static_cast<double>(sim_frame + 1) * dt_s : sim_time_s;
  }
  /// The stamp of a sample sampled at the start of the frame (inputs, commands).
  msg::FrameStamp stamp() const { return make_stamp(sim_time_s); }
  /// The stamp of a state computed by the frame's step: valid at the end of the frame.
  msg::FrameStamp end_stamp() const { return make_stamp(end_time_s()); }

 private:
  msg::FrameStamp make_stamp(double time_s) const {
    msg::FrameStamp s;
    s.frame(frame);
    s.sim_time_s(time_s);
    return s;
  }
};

enum class PortDirection { kRead, kWrite };

/// A port as the graph and the hosts see it.
struct PortInfo {
  const TopicInfo* topic = nullptr;
  PortDirection direction = PortDirection::kRead;
  std::string qos;              // QoS profile this port uses
  bool lockstep_input = false;  // reads: frame N waits for the frame N-1 sample in lockstep
  bool monitor = false;         // reads: declared by monitors(): optional, never holds a frame
};

/// Which writer a sample came from, as far as the host can tell (over DDS the writer's instance
/// handle; in-process all zero): enough to name the writer whose liveliness lapses later.
using WriterId = std::array<std::uint8_t, 16>;

template <class T>
class Input;
template <class T>
class Output;

// The message types a port can carry (the catalogue's). A host implements one bind() per type
// and direction, so that the component layer needs no DDS template.
#define FEDSIM_PORT_MESSAGE_TYPES(X) \
  X(FrameTick)                       \
  X(FrameDone)                       \
  X(SimCommand)                      \
  X(FederateStatus)                  \
  X(PilotControls)                   \
  X(AircraftState)                   \
  X(EngineState)                     \
  X(NavigationState)                 \
  X(AutopilotState)                  \
  X(MotionPlatformState)             \
  X(ControlLoadingState)             \
  X(VisualChannelStatus)             \
  X(VisualPicture)

class PortBinder {
 public:
  virtual ~PortBinder() = default;
#define FEDSIM_DECLARE_BIND(Msg)                       \
  virtual void bind(Input<msg::Msg>& port) = 0;        \
  virtual void bind(Output<msg::Msg>& port) = 0;
  FEDSIM_PORT_MESSAGE_TYPES(FEDSIM_DECLARE_BIND)
#undef FEDSIM_DECLARE_BIND
};

class PortBase {
 public:
  explicit PortBase(PortInfo info) : info_(std::move(info)) {}
  virtual ~PortBase() = default;
  const PortInfo& info() const { return info_; }
  const std::string& topic_name() const { return info_.topic->name; }
  virtual void bind(PortBinder& binder) = 0;

 protected:
  PortInfo info_;
};

/// A read port. The host refreshes it before every step.
template <class T>
class Input final : public PortBase {
 public:
  using PortBase::PortBase;
  /// The sample this frame reads, or nullptr while none has arrived.
  const T* latest() const { return valid_ ? &value_ : nullptr; }
  /// Samples refreshed into this port so far (a new one each frame its writer wrote).
  std::uint64_t updates() const { return updates_; }
  /// Writers matched to this port now (over DDS; -1 where the host does not know: in-process).
  /// More than one writer of a topic a component expects one owner of is worth a warning.
  int writers() const { return writers_ ? writers_() : -1; }
  void bind(PortBinder& binder) override { binder.bind(*this); }
  /// Only samples `accept` returns true for reach this port: the host applies it as samples
  /// arrive, so another's sample is never read and never counts as the frame's input (e.g. one
  /// aircraft's controls on a topic keyed by aircraft). Set in the constructor, before binding;
  /// over DDS it runs on a middleware thread.
  void accept_only(std::function<bool(const T&)> accept) { accept_ = std::move(accept); }
  /// Calls `handler` with every sample that reaches this port, as it arrives, besides keeping
  /// the latest for the step: for what must see each sample rather than each frame's newest
  /// (the frame clock's acknowledgements, the instructor station's view of every engine). Over
  /// DDS on a middleware thread; in-process when the frame that wrote it ends. Set before binding.
  using ArrivalHandler = std::function<void(const T&, const WriterId&)>;
  void on_arrival(ArrivalHandler handler) { arrival_ = std::move(handler); }
  /// Calls `handler` with a writer whose liveliness lapsed (a process gone or hung; over DDS
  /// only, on a middleware thread). Set before binding.
  void on_writer_lost(std::function<void(const WriterId&)> handler) { writer_lost_ = std::move(handler); }

  // Host side.
  const std::function<bool(const T&)>& acceptor() const { return accept_; }
  const ArrivalHandler& arrival() const { return arrival_; }
  const std::function<void(const WriterId&)>& writer_lost() const { return writer_lost_; }
  void set_writer_count(std::function<int()> count) { writers_ = std::move(count); }
  T& slot() { return value_; }
  void mark_updated() {
    valid_ = true;
    ++updates_;
  }
  void clear() { valid_ = false; }

 private:
  T value_{};
  bool valid_ = false;
  std::uint64_t updates_ = 0;
  std::function<int()> writers_;
  std::function<bool(const T&)> accept_;
  ArrivalHandler arrival_;
  std::function<void(const WriterId&)> writer_lost_;
};

/// A write port. write() hands the sample to the host at once (the DDS writer, or the
/// in-process frame buffer).
template <class T>
class Output final : public PortBase {
 public:
  using Sink = std::function<bool(const T&)>;
  using PortBase::PortBase;
  /// Writes one sample; false if the host refused it (counted in refused()).
  bool write(const T& sample) {
    ++written_;
    if (sink_ && sink_(sample)) return true;
    ++refused_;
    return false;
  }
  std::uint64_t written() const { return written_; }
  std::uint64_t refused() const { return refused_; }
  /// Readers matched to this port now (over DDS; -1 where the host does not know: in-process).
  int readers() const { return readers_ ? readers_() : -1; }
  void bind(PortBinder& binder) override { binder.bind(*this); }

  // Host side.
  void set_sink(Sink sink) { sink_ = std::move(sink); }
  void set_reader_count(std::function<int()> count) { readers_ = std::move(count); }

 private:
  Sink sink_;
  std::function<int()> readers_;
  std::uint64_t written_ = 0;
  std::uint64_t refused_ = 0;
};

/// What a host offers a component besides its ports.
struct HostServices {
  /// The DDS participant the ports are bound to (nullptr in-process): for the rare entity a
  /// catalogue port cannot express (the instructor station replays a recording through Fast
  /// DDS's dynamic types).
  std::shared_ptr<DdsParticipant> dds;
};

/// Faults a component met while stepping (numerical faults, rejected inputs...), counted by
/// kind and reported by the host in the federate status and the final summary.
struct FaultReport {
  std::string kind;     // e.g. "numerical", "input_rejected"
  std::uint64_t count = 0;
  std::string last;     // the latest message of that kind
};

class Component {
 public:
  explicit Component(std::string name);
  virtual ~Component();
  Component(const Component&) = delete;
  Component& operator=(const Component&) = delete;

  const std::string& name() const { return name_; }
  const std::vector<std::unique_ptr<PortBase>>& ports() const { return ports_; }

  /// Once, when a host is about to run it, before its ports are bound: acquire here what only a
  /// running component needs (a listening socket, a database), never in the constructor, which
  /// also builds it for `--print-ports` and `fedsim graph`. Throws to refuse to run (over DDS
  /// the program exits 2).
  virtual void on_start(const HostServices& host) {}
  /// Instructor commands, delivered just before the step of the frame they arrived in (never in
  /// the middle of a step). SHUTDOWN is the host's.
  virtual void on_command(const msg::SimCommand& command) {}
  /// One frame: read the inputs, step the model, write the outputs.
  virtual void step(const FrameContext& frame) = 0;
  /// Once, after the last step (flush files here).
  virtual void on_stop() {}
  /// The tick watchdog, realtime only: when no frame tick has arrived for more than this many
  /// frame periods (0: never), the host calls on_ticks_stopped() from its frame thread, at once
  /// and then on every wake-up (about every 20 ms) until a tick comes. For what must go safe on
  /// its own when the federation stops driving it (control loading, motion): with no tick,
  /// step() never runs. Lockstep has no such watch: its time stops with the ticks.
  virtual double tick_watchdog_periods() const { return 0.0; }
  /// `last`: the context of the last frame stepped; `silent_s`: wall time since its tick.
  virtual void on_ticks_stopped(const FrameContext& last, double silent_s) {}
  /// A short line for whoever watches the run (the flight federate: phase of flight, distance
  /// to go, modes), sent with the periodic status (FederateStatus.message, 127 characters) and
  /// shown in `fedsim run`'s progress lines. Called between steps; empty: nothing to say.
  virtual std::string progress_note() const { return {}; }

  /// The faults reported so far, by kind.
  const std::vector<FaultReport>& faults() const { return faults_; }
  std::uint64_t fault_count() const;

  /// Host side: counts a fault the host found on one of the component's ports (a silent
  /// writer), reported with the component's own faults.
  void report_port_fault(const std::string& kind, const std::string& message) {
    report_fault(kind, message);
  }

  /// Where the component logs (the host's logger once bound; a default one until then).
  spdlog::logger& log() const { return *log_; }
  void set_logger(std::shared_ptr<spdlog::logger> logger) { log_ = std::move(logger); }

 protected:
  /// Declares a read port on a catalogue topic; `qos` overrides the topic's default profile.
  template <class T>
  Input<T>& reads(const Topic<T>& topic, std::string_view qos = {}) {
    return add<Input<T>>(topic.info, PortDirection::kRead, qos, topic.info.lockstep_input);
  }
  /// Declares a read port that never holds the frame back (a monitor of a topic).
  template <class T>
  Input<T>& monitors(const Topic<T>& topic, std::string_view qos = {}) {
    return add<Input<T>>(topic.info, PortDirection::kRead, qos, false, true);
  }
  /// Declares a write port on a catalogue topic.
  template <class T>
  Output<T>& writes(const Topic<T>& topic, std::string_view qos = {}) {
    return add<Output<T>>(topic.info, PortDirection::kWrite, qos, false);
  }
  /// Counts a fault of `kind` and logs its message (rate-limited: the first and then every
  /// 100th of a kind).
  void report_fault(const std::string& kind, const std::string& message);

 private:
  template <class P>
  P& add(const TopicInfo& topic, PortDirection direction, std::string_view qos, bool lockstep,
         bool monitor = false) {
    PortInfo info{&topic, direction, qos.empty() ? topic.default_qos : std::string(qos), lockstep, monitor};
    auto port = std::make_unique<P>(std::move(info));
    P& ref = *port;
    ports_.push_back(std::move(port));
    return ref;
  }

  std::string name_;
  std::vector<std::unique_ptr<PortBase>> ports_;
  std::vector<FaultReport> faults_;
  std::shared_ptr<spdlog::logger> log_;
};

/// A component that makes the federation's frames rather than stepping in them: the frame clock
/// (fedsim-timing), the writer of fedsim/frame_tick. Its ports are bound as any component's, but
/// the DDS host (Federate::run) neither reads ticks for it nor acknowledges frames: it calls
/// drive() on its frame thread, first once it is bound, then when the time drive() returned has
/// come or the driver called wake() (from any thread: an acknowledgement, a status). Commands
/// reach it on its own ports (it must act on them on arrival); SHUTDOWN, signals and
/// on_stop() are the host's as for every component. --frames and --duration are the driver's
/// own to count (from its first frame), not the host's.
class Driver : public Component {
 public:
  using Component::Component;

  /// Does what is due at `now_ns` (CLOCK_MONOTONIC) and returns the time of the next call, or
  /// nullopt when its run is over (fail() first, if it failed).
  virtual std::optional<std::uint64_t> drive(std::uint64_t now_ns) = 0;

  /// What the host's status says of it: whether it makes frames yet, how many, how many overran.
  struct Progress {
    bool running = false;
    std::uint64_t frames = 0;
    std::uint64_t overruns = 0;
  };
  virtual Progress progress() const = 0;

  // Host side.
  /// The host's doorbell (set before the first drive()).
  void set_waker(std::function<void()> wake) { waker_ = std::move(wake); }
  /// Lines published at once in the driver's own status (fedsim run shows them), oldest first.
  std::vector<std::string> take_notes();
  /// Set by finish(): the run's end was a failure with this exit code and reason (0: clean).
  int exit_code() const { return exit_code_; }
  const std::string& failure() const { return failure_; }

 protected:
  /// Asks the host to call drive() now (any thread).
  void wake() const {
    if (waker_) waker_();
  }
  /// Queues a line for the status (any thread; published by the host's frame thread, never
  /// under the caller's locks: a status written comes straight back to this process's reader).
  void note(std::string line);
  /// Makes the end of the run a failure (call before drive() returns nullopt).
  void fail(int exit_code, std::string reason) {
    exit_code_ = exit_code;
    failure_ = std::move(reason);
  }

 private:
  void step(const FrameContext&) final {}

  std::function<void()> waker_;
  std::mutex notes_mutex_;
  std::vector<std::string> notes_;
  int exit_code_ = 0;
  std::string failure_;
};

/// The ports of a component as one JSON document ({"federate": name, "ports": [...]}) - what
/// `<federate> --print-ports` prints and `fedsim graph` reads.
std::string ports_json(const Component& component);

}  // namespace fedsim::runtime
