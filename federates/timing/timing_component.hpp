// fedsim-timing: publishes the frame tick (the seed's node-1 start of frame, section 2.11).
//
// Subscribes: fedsim/frame_done ("frame_done", liveliness tells a dead federate),
//             fedsim/federate_status ("status"), fedsim/sim_command ("command").
// Publishes:  fedsim/frame_tick ("tick") every frame, fedsim/federate_status ("status").
//
// Modes: realtime - ticks on absolute CLOCK_MONOTONIC deadlines; a frame whose acknowledgements
//                   are not all in by the next deadline is an overrun (counted, reported).
//        lockstep - the next tick only after every expected federate acknowledged the current
//                   one; as fast as possible (scale 0) or paced at `scale` x real time.
// A federate that stops acknowledging is reported lost and dropped from the expected set, so
// lockstep never hangs, in both modes within --ack-timeout of the first tick it did not
// acknowledge (model/loss_watch.hpp), sooner when it says it stops or fails, when a new process
// reports under its name, or when the liveliness of its frame_done writer (1.5 s lease) lapses
// (seen for a killed process; never for a SIGSTOPped one with Fast DDS 2.9 here, in 6 s, with
// either sync QoS: the acknowledgement age is the bound that holds). A lost federate that reports READY
// or RUNNING again (restarted, or continued after SIGSTOP) is expected again from the next tick
// ("rejoined"); a new process under a known name counts as lost and rejoined. Each loss and
// rejoin is logged, published on fedsim/federate_status (the lost federate's instance in state
// LOST, and a message in the timing federate's own status) and listed in the summary.
//
// Command holder: the timing federate (always in the federation) keeps the latest setting of
// each kind and target seen on fedsim/sim_command (weather, failures, radios, time of day; see
// common/runtime/command_settings.hpp) and republishes it unchanged from its own
// transient-local writer, so a federate restarted after the `fedsim command` that sent it
// exited still gets it (--hold-commands=false turns this off).
#pragma once

#include "common/runtime/dds_participant.hpp"
#include "common/runtime/federate_options.hpp"
#include "common/runtime/publisher.hpp"
#include "common/runtime/subscription.hpp"
#include "common/util/latency_stats.hpp"
#include "common/runtime/command_settings.hpp"
#include "timing/model/ack_tracker.hpp"
#include "timing/model/loss_watch.hpp"
#include "common/frame_clock/run_control.hpp"

#include <spdlog/logger.h>

#include <condition_variable>
#include <map>
#include <mutex>
#include <set>
#include <string>
#include <vector>

namespace fedsim::timing {

struct TimingOptions {
  runtime::FederateOptions common;
  double rate_hz = 50.0;               // frame rate [Hz]
  std::string mode = "realtime";       // realtime | lockstep
  double scale = 0.0;                  // lockstep pacing: 0 = as fast as possible, 1 = real time
  std::vector<std::string> expect;     // federates that must acknowledge every frame
  std::string start = "run";           // run | freeze: state of the first frame
  double ack_timeout_s = 5.0;          // a federate silent this long is declared lost
  double resend_after_s = 0.25;        // lockstep: repeat a tick whose acks are overdue
  double join_timeout_s = 30.0;        // wait this long for the expected federates to be ready
  double settle_s = 0.3;               // after everyone is ready, let discovery finish
  bool stop_on_lost = false;           // stop the federation when a federate is lost
  bool shutdown_on_exit = false;       // publish a SHUTDOWN command when the timing stops
  std::string summary_json;            // also write the summary JSON to this file
  bool hold_commands = true;           // republish the latest settings for late joiners
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
  std::size_t held_settings = 0;
  util::LatencyStats all_acked;     // tick publish -> last acknowledgement
  util::LatencyStats period_error;  // realtime: actual - scheduled tick time
};

class TimingFederate {
 public:
  explicit TimingFederate(TimingOptions options);
  ~TimingFederate();
  /// Runs until --frames/--duration/signal/SHUTDOWN; returns the exit code.
  int run();
  TimingSummary summary() const;
  std::string summary_json() const;

 private:
  void on_ack(const msg::FrameDone& ack, const runtime::fdds::SampleInfo& info);
  void on_status(const msg::FederateStatus& status);
  void rejoin_locked(const std::string& federate, const std::string& how);
  void hold_command(const msg::SimCommand& command);
  void on_command(const msg::SimCommand& command);
  void on_liveliness(const runtime::fdds::LivelinessChangedStatus& status);
  bool wait_for_federation();
  void run_realtime();
  void run_lockstep();
  void publish_tick_locked();
  void republish_tick_locked();
  void remember_writer_locked(const eprosima::fastrtps::rtps::InstanceHandle_t& handle,
                              const std::string& federate);
  void mark_lost_locked(const std::string& federate, const std::string& why);
  void check_ack_timeout_locked(std::uint64_t now_ns);
  double run_time_s_locked() const;
  void publish_lost_statuses();
  bool should_stop_locked() const;
  bool frames_exhausted_locked() const;
  void publish_status(msg::FederateState state, const std::string& message);
  void flush_status_messages();
  bool status_due_locked() const;

  TimingOptions options_;
  std::shared_ptr<spdlog::logger> log_;
  std::shared_ptr<runtime::DdsParticipant> dds_;
  std::unique_ptr<runtime::Publisher<msg::FrameTick>> tick_pub_;
  std::unique_ptr<runtime::Publisher<msg::FederateStatus>> status_pub_;
  std::unique_ptr<runtime::Publisher<msg::SimCommand>> command_pub_;
  std::unique_ptr<runtime::Subscription<msg::FrameDone>> ack_sub_;
  std::unique_ptr<runtime::Subscription<msg::FederateStatus>> status_sub_;
  std::unique_ptr<runtime::Subscription<msg::SimCommand>> command_sub_;

  mutable std::mutex mutex_;
  std::condition_variable cv_;
  AckTracker tracker_;
  RunControl run_control_;
  msg::FrameTick tick_;
  bool lockstep_ = false;
  bool started_ = false;
  bool stopping_ = false;
  std::uint64_t ticks_published_ = 0;
  std::uint64_t tick_publish_ns_ = 0;
  std::uint64_t last_resend_ns_ = 0;
  std::uint64_t start_ns_ = 0;
  std::uint64_t end_ns_ = 0;
  std::set<std::string> ready_;
  // frame_done writer -> federate (to name a federate whose liveliness is lost)
  std::vector<std::pair<eprosima::fastrtps::rtps::InstanceHandle_t, std::string>> writers_;
  LossWatch loss_watch_;
  std::vector<std::pair<std::string, std::uint32_t>> lost_to_publish_;  // name, pid (under mutex_)
  mutable std::mutex holder_mutex_;
  runtime::SettingHolder holder_;
  TimingSummary summary_;
  std::vector<std::string> status_messages_;
  std::uint64_t next_status_ns_ = 0;  // queued under mutex_, published outside it
  std::string stop_reason_;
  int exit_code_ = 0;
};

}  // namespace fedsim::timing
