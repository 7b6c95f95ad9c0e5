// fedsim-timing: the federation's frame clock (the seed's node-1 start of frame, section 2.11), a
// runtime::Driver: the DDS host drives it on its frame thread instead of stepping it
// (common/runtime/component.hpp). Every decision is model/timekeeper's (pure, tested with a fake
// clock); this adapter turns port samples into its inputs and its decisions into samples.
//
// Ports (--print-ports):
//   writes fedsim/frame_tick      ("tick", "tick_reliable" with --sync-qos reliable) every frame
//          fedsim/federate_status ("status") a lost member's own instance, in state LOST
//          fedsim/sim_command     ("command") the settings it holds, republished
//   reads  fedsim/frame_done      ("frame_done"...) every acknowledgement; the liveliness of its
//                                 writers tells a dead member
//          fedsim/federate_status ("status") who is ready, stops, fails or is back
//          fedsim/sim_command     ("command") run-state requests, settings to hold, shutdown
// Its own status (READY, RUNNING with its frame count, a line for each loss and rejoin,
// STOPPING) is the host's, as for every federate.
//
// Modes and losses: see model/timekeeper.hpp. The liveliness of a member's frame_done writer
// (1.5 s lease) lapses for a killed process; never for a SIGSTOPped one with Fast DDS 2.9 here,
// in 6 s, with either sync QoS: the acknowledgement age is the bound that holds. Each loss and
// rejoin is logged, published on fedsim/federate_status and listed in the summary (printed as
// one JSON line at the end, and written to --summary-json).
//
// Command holder: the clock (always in the federation) keeps the latest setting of each kind
// and target seen on fedsim/sim_command (weather, failures, radios, time of day; see
// common/runtime/command_settings.hpp) and republishes it unchanged from its own
// transient-local writer, so a federate restarted after the `fedsim command` that sent it
// exited still gets it (--no-hold-commands turns this off).
//
// Threads: acknowledgements, statuses and commands are taken on the middleware's threads, under
// one mutex; in lockstep as fast as possible the next tick goes out right on the thread of the
// acknowledgement that completed the frame. Everything else (the join, realtime deadlines,
// repeated ticks, timeouts, LOST statuses) happens in drive(), on the host's frame thread.
// Statuses and held commands are written outside the mutex: a sample written comes straight
// back to this process's own reader, whose handler takes it.
#pragma once

#include "common/runtime/command_settings.hpp"
#include "common/runtime/component.hpp"
#include "common/runtime/federate_main.hpp"
#include "timing/model/timekeeper.hpp"

#include <mutex>
#include <string>
#include <utility>
#include <vector>

namespace fedsim::timing {

struct TimingOptions {
  runtime::FederateOptions common;     // --frames and --duration count from the first tick
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

/// The clock's settings from the program's options (throws std::invalid_argument naming a bad one).
TimekeeperSettings timekeeper_settings(const TimingOptions& options);

class TimingComponent final : public runtime::Driver {
 public:
  explicit TimingComponent(TimingOptions options);

  std::optional<std::uint64_t> drive(std::uint64_t now_ns) override;
  Progress progress() const override;
  void on_stop() override;

  const TimingOptions& options() const { return options_; }
  TimingSummary summary() const;
  std::string summary_json() const;

  // The arrivals, as the ports deliver them (public for the tests, which drive them by hand).
  void on_ack(const msg::FrameDone& ack, const runtime::WriterId& writer, std::uint64_t now_ns);
  void on_status(const msg::FederateStatus& status, std::uint64_t now_ns);
  void on_command_sample(const msg::SimCommand& command);
  void on_writer_lost(const runtime::WriterId& writer, std::uint64_t now_ns);

 private:
  std::optional<std::uint64_t> join_locked(std::uint64_t now_ns);
  void publish_tick_locked(std::uint64_t now_ns);
  void handle_reports_locked();
  void hold_command(const msg::SimCommand& command);
  void publish_lost_statuses();

  TimingOptions options_;
  runtime::Output<msg::FrameTick>& ticks_;
  runtime::Output<msg::FederateStatus>& lost_status_;
  runtime::Output<msg::SimCommand>& held_commands_;
  runtime::Input<msg::FrameDone>& acks_;
  runtime::Input<msg::FederateStatus>& statuses_;
  runtime::Input<msg::SimCommand>& commands_;

  mutable std::mutex mutex_;
  Timekeeper keeper_;
  msg::FrameTick tick_;
  bool waiting_logged_ = false;
  // frame_done writer -> member (to name a member whose liveliness lapses)
  std::vector<std::pair<runtime::WriterId, std::string>> writers_;
  std::vector<std::pair<std::string, std::uint32_t>> lost_to_publish_;  // name, pid (under mutex_)
  mutable std::mutex holder_mutex_;
  runtime::SettingHolder holder_;
  // The command port is written from a middleware thread (a setting to hold) and at the end from
  // the frame thread (SHUTDOWN). Never taken where a write comes back to a writing path: a
  // setting coming back is held already, SHUTDOWN is no setting.
  std::mutex command_write_mutex_;
};

/// fedsim-timing's options and component (main.cpp, fedsim run --in-process, fedsim graph).
runtime::FederateProgram program();

}  // namespace fedsim::timing
