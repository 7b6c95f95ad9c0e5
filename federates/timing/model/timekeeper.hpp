// The frame clock's decisions, fedsim-timing's whole logic (pure: no DDS, no clock; every time is
// passed in, CLOCK_MONOTONIC nanoseconds, so a test drives it with a fake clock):
//   - the join: every expected member reported READY or RUNNING and the DDS matches count them
//     all (tick readers, acknowledgement writers), then `settle_s` for the other halves of the
//     matches; or the join timeout;
//   - when a tick goes out:
//       realtime - on absolute deadlines (first + n periods); a frame whose acknowledgements are
//                  not all in by the next deadline is an overrun (counted, reported);
//       lockstep - the next tick only when every expected member acknowledged the current one;
//                  as fast as possible (scale 0: at once, on the acknowledgement that completed
//                  the frame) or paced at `scale` x real time; a tick whose acknowledgements are
//                  `resend_after_s` overdue is repeated;
//   - who is lost (silent for the acknowledgement timeout, model/loss_watch.hpp; stopped or
//     failed; its process replaced; its liveliness lapsed) and who is back (READY or RUNNING
//     again: expected from the next tick), model/ack_tracker.hpp keeping the expected set;
//   - the run state (common/frame_clock/run_control.hpp) and when the run ends (--frames,
//     --duration from the first tick, a stop, --stop-on-lost);
//   - the summary (frames, overruns, repeated ticks, losses and rejoins, acknowledgement latency,
//     realtime period error) and its JSON.
// What happened that a watcher should hear of (a loss, a rejoin, an overrun) is queued as a
// Report for the adapter to log and publish.
#pragma once

#include "common/frame_clock/run_control.hpp"
#include "common/util/latency_stats.hpp"
#include "timing/model/ack_tracker.hpp"
#include "timing/model/loss_watch.hpp"

#include <cstdint>
#include <set>
#include <string>
#include <vector>

namespace fedsim::timing {

enum class ClockMode { kRealtime, kLockstep };

struct TimekeeperSettings {
  double rate_hz = 50.0;              // frame rate [Hz]
  ClockMode mode = ClockMode::kRealtime;
  double scale = 0.0;                 // lockstep pacing: 0 = as fast as possible, 1 = real time
  std::vector<std::string> expect;    // members that must acknowledge every frame
  RunState start = RunState::kRun;    // state of the first frame (run or freeze)
  double ack_timeout_s = 5.0;         // a member silent this long is declared lost [s]
  double resend_after_s = 0.25;       // lockstep: repeat a tick whose acknowledgements are overdue [s]
  double join_timeout_s = 30.0;       // wait this long for the expected members to be ready [s]
  double settle_s = 0.3;              // after everyone is ready, let discovery finish [s]
  bool stop_on_lost = false;          // end the run when a member is lost
  std::uint64_t max_frames = 0;       // end after this many ticks (0 = no limit)
  double duration_s = 0.0;            // end this long after the first tick (0 = no limit) [s]
};

/// A member's state as its status reports it.
enum class MemberState { kStarting, kReady, kRunning, kStopping, kFailed, kLost };

/// Something a watcher should hear of.
struct Report {
  enum class Kind { kLost, kRejoined, kOverrun };
  Kind kind;
  std::string federate;          // lost, rejoined: who
  std::uint64_t frame = 0;       // lost: the frame waited for; rejoined: its first frame back;
                                 // overrun: the frame not complete at its deadline
  std::string detail;            // lost: why; rejoined: how; overrun: the members missing
  std::uint32_t pid = 0;         // lost: its last known process
  std::uint64_t overruns = 0;    // overrun: the count so far
};

struct TimingSummary {
  std::uint64_t frames = 0;
  double wall_s = 0.0;
  std::uint64_t overruns = 0;
  std::uint64_t resent_ticks = 0;
  std::vector<std::string> lost;      // every loss, in order
  std::vector<std::string> rejoined;  // every rejoin, in order
  std::vector<std::string> still_lost;
  std::vector<MembershipEvent> events;
  util::LatencyStats all_acked;     // tick issued -> last acknowledgement
  util::LatencyStats period_error;  // realtime: actual - scheduled tick time
};

class Timekeeper {
 public:
  /// Throws std::invalid_argument naming a setting that is not finite or out of range.
  explicit Timekeeper(TimekeeperSettings settings);

  const TimekeeperSettings& settings() const { return settings_; }
  bool lockstep() const { return settings_.mode == ClockMode::kLockstep; }

  // ---- What arrives (any time; the adapter serialises the calls).

  /// A member's status (`pid` 0: unknown). One that stops with a message starting "shutdown
  /// command" stops because the federation was told to: not a loss.
  void status(const std::string& federate, MemberState state, std::uint32_t pid,
              const std::string& message, std::uint64_t now_ns);
  enum class Ack {
    kNothing,    // not the last one the frame waited for
    kCompleted,  // completed the frame; the next tick comes from wake()
    kTickNow,    // completed the frame, and the next tick is due at once (lockstep, scale 0)
  };
  Ack acknowledge(const std::string& federate, std::uint64_t frame, std::uint64_t now_ns);
  /// The liveliness of a member's acknowledgement writer lapsed.
  void liveliness_lost(const std::string& federate, std::uint64_t now_ns);
  /// An instructor's run-state request; it takes effect at the next tick.
  void request(RunState state) { run_control_.request(state); }
  /// Ends the run (a shutdown command, a signal): no tick after this.
  void stop(std::string reason);

  // ---- The join.
  enum class Join { kWaiting, kSettling, kReady, kTimedOut };
  /// Where the assembly stands at `now_ns` (the first call starts the join timeout).
  Join join(std::uint64_t now_ns, int tick_readers, int ack_writers);
  /// Expected members that have not reported READY or RUNNING.
  std::vector<std::string> not_ready() const;
  /// When join() needs to look again (settling ends).
  std::uint64_t settle_until_ns() const { return settle_until_ns_; }

  // ---- The run.
  void start(std::uint64_t now_ns);
  bool started() const { return started_; }
  struct Due {
    bool tick = false;       // issue_tick() now and publish it
    bool resend = false;     // publish the current tick again (counted)
    bool finished = false;   // the run is over
    std::uint64_t next_ns = 0;  // when to call wake() again (unless something arrives)
  };
  /// What is due at `now_ns`. Realtime: call at least at each next_ns. Lockstep: also after an
  /// acknowledgement said kCompleted.
  Due wake(std::uint64_t now_ns);
  /// The next tick's fields (a new frame: the expected set waits for it); `now_ns` its issue time.
  TickFields issue_tick(std::uint64_t now_ns);
  /// Ends the run's clock (the wall time of the summary; later calls change nothing).
  void finish(std::uint64_t now_ns);

  std::uint64_t frames() const { return ticks_issued_; }
  std::uint64_t overruns() const { return summary_.overruns; }
  std::uint64_t frame() const { return tracker_.frame(); }
  const std::string& stop_reason() const { return stop_reason_; }
  /// 1 when the run ended because a member was lost and --stop-on-lost; else 0.
  int exit_code() const { return exit_code_; }
  bool stopping() const { return stopping_; }

  /// What happened since the last call, oldest first.
  std::vector<Report> take_reports();
  TimingSummary summary() const;
  /// The summary as one line of JSON (`federate`: the clock's name; `held_settings`: the
  /// adapter's command holder's count).
  std::string summary_json(const std::string& federate, std::size_t held_settings) const;

 private:
  bool should_stop(std::uint64_t now_ns) const;
  bool frames_exhausted() const;
  double run_time_s(std::uint64_t now_ns) const;
  void mark_lost(const std::string& federate, const std::string& why, std::uint64_t now_ns);
  void rejoin(const std::string& federate, const std::string& how, std::uint64_t now_ns);
  void check_ack_timeouts(std::uint64_t now_ns);
  bool is_member(const std::string& federate) const;
  Due wake_realtime(std::uint64_t now_ns);
  Due wake_lockstep(std::uint64_t now_ns);

  TimekeeperSettings settings_;
  std::uint64_t period_ns_;
  std::uint64_t resend_ns_;
  AckTracker tracker_;
  RunControl run_control_;
  LossWatch loss_watch_;
  std::set<std::string> ready_;
  std::uint64_t join_started_ns_ = 0;
  std::uint64_t settle_until_ns_ = 0;
  bool started_ = false;
  bool stopping_ = false;
  bool finished_ = false;
  std::uint64_t start_ns_ = 0;
  std::uint64_t ticks_issued_ = 0;
  std::uint64_t tick_issued_ns_ = 0;
  std::uint64_t last_resend_ns_ = 0;
  std::uint64_t deadlines_passed_ = 0;  // realtime: deadlines ticked so far
  std::uint64_t drain_until_ns_ = 0;    // realtime: the last frame's acknowledgements may come
  std::string stop_reason_;
  int exit_code_ = 0;
  TimingSummary summary_;
  std::vector<Report> reports_;
};

}  // namespace fedsim::timing
