#include "tools/topic/topic_commands.hpp"
#include "common/util/cli_checks.hpp"

#include "tools/topic/topic_replay.hpp"
#include "tools/topic/topic_tools.hpp"

#include "common/runtime/federate_options.hpp"

#include <iostream>
#include <memory>

namespace fedsim::tools {

namespace {

void exit_with(int code) {
  if (code != 0) throw CLI::RuntimeError(code);
}

void add_list(CLI::App& topic) {
  auto options = std::make_shared<ListOptions>();
  auto* cmd = topic.add_subcommand("list", "list the live topics with their type and endpoints");
  cmd->add_flag("-v,--verbose", options->verbose,
                "show each writer's and reader's participant and QoS");
  cmd->add_option("--wait", options->wait_s, "discovery time [s]")
      ->check(fedsim::util::kFiniteNonNegative)
      ->capture_default_str();
  runtime::add_dds_options(*cmd, options->dds);
  cmd->callback([options] { exit_with(run_topic_list(*options, std::cout, std::cerr)); });
}

void add_echo(CLI::App& topic) {
  auto options = std::make_shared<EchoOptions>();
  auto* cmd = topic.add_subcommand("echo", "print the samples of a topic (any fedsim type)");
  cmd->add_option("topic", options->topic, "topic name, e.g. fedsim/aircraft_state")->required();
  cmd->add_option("-n,--count", options->count, "stop after N samples (0 = until Ctrl-C)")
      ->capture_default_str();
  cmd->add_option("--field", options->field,
                  "print only this field, e.g. stamp.frame, velocity_ned_mps[2], gear[0]");
  cmd->add_flag("--json", options->json, "one JSON object per line instead of YAML");
  cmd->add_option("--wait", options->wait_s, "how long to wait for the topic to appear [s]")
      ->check(fedsim::util::kFiniteNonNegative)
      ->capture_default_str();
  cmd->add_option("--timeout", options->timeout_s,
                  "fail if --count samples have not arrived in this time [s] (0 = wait forever)")
      ->check(fedsim::util::kFiniteNonNegative);
  runtime::add_dds_options(*cmd, options->dds);
  cmd->callback([options] { exit_with(run_topic_echo(*options, std::cout, std::cerr)); });
}

/// The options `hz` and `bw` share: the topic, a sliding window of samples, how long to wait for
/// the topic, how long to run.
template <class Options>
CLI::App* add_window_command(CLI::App& topic, const std::string& name, const std::string& what,
                             const std::shared_ptr<Options>& options, double min_window) {
  auto* cmd = topic.add_subcommand(name, what);
  cmd->add_option("topic", options->topic, "topic name")->required();
  cmd->add_option("-w,--window", options->window, "samples in the sliding window")
      ->check(fedsim::util::FiniteRange(min_window, 100000000))
      ->capture_default_str();
  cmd->add_option("--wait", options->wait_s, "how long to wait for the topic to appear [s]")
      ->check(fedsim::util::kFiniteNonNegative)
      ->capture_default_str();
  cmd->add_option("--duration", options->duration_s, "stop after this many seconds (0 = Ctrl-C)")
      ->check(fedsim::util::kFiniteNonNegative);
  runtime::add_dds_options(*cmd, options->dds);
  return cmd;
}

void add_hz(CLI::App& topic) {
  auto options = std::make_shared<HzOptions>();
  auto* cmd = add_window_command(topic, "hz", "print the receive rate of a topic once a second", options, 2);
  cmd->callback([options] { exit_with(run_topic_hz(*options, std::cout, std::cerr)); });
}

void add_bw(CLI::App& topic) {
  auto options = std::make_shared<BwOptions>();
  auto* cmd = add_window_command(
      topic, "bw", "print the bandwidth of a topic once a second: bytes/s, samples/s, sample sizes", options, 1);
  cmd->callback([options] { exit_with(run_topic_bw(*options, std::cout, std::cerr)); });
}

void add_info(CLI::App& topic) {
  auto options = std::make_shared<InfoOptions>();
  auto* cmd = topic.add_subcommand(
      "info", "show a topic's type and every writer's and reader's QoS, participant and locators");
  cmd->add_option("topic", options->topic, "topic name")->required();
  cmd->add_option("--wait", options->wait_s, "discovery time [s]")
      ->check(fedsim::util::kFiniteNonNegative)
      ->capture_default_str();
  runtime::add_dds_options(*cmd, options->dds);
  cmd->callback([options] { exit_with(run_topic_info(*options, std::cout, std::cerr)); });
}

void add_record(CLI::App& app) {
  auto options = std::make_shared<RecordOptions>();
  auto* cmd = app.add_subcommand("record", "record topics to CSV files, one per topic");
  cmd->add_option("--topics", options->topics, "topics to record, comma-separated")
      ->required()
      ->delimiter(',');
  cmd->add_option("--out", options->out_dir, "output directory (created if missing)")->required();
  cmd->add_option("--duration", options->duration_s, "stop after this many seconds (0 = Ctrl-C)")
      ->check(fedsim::util::kFiniteNonNegative);
  cmd->add_flag("--lockstep-member", options->lockstep_member,
                "join the federation as a lockstep federate: every frame is recorded before it "
                "is acknowledged");
  cmd->add_option("--name", options->name, "participant / federate name")->capture_default_str();
  cmd->add_option("--wait", options->wait_s, "discovery time for the topics' writers [s]")
      ->check(fedsim::util::kFiniteNonNegative)
      ->capture_default_str();
  cmd->add_option("--progress", options->progress_period_s,
                  "print samples written per topic every S seconds (0 = never)")
      ->check(fedsim::util::kFiniteNonNegative)
      ->capture_default_str();
  cmd->add_option("--reader-profile", options->reader_profile,
                  "data_reader QoS profile for every topic (default: match the writers' QoS)");
  cmd->add_option("--frames", options->max_frames,
                  "lockstep member: stop after this many frames (0 = no limit)");
  runtime::add_sync_qos_option(*cmd, options->sync_qos_suffix,
                               "lockstep member: tick/acknowledgement QoS, best_effort | reliable");
  cmd->add_option("--input-timeout", options->input_timeout_s,
                  "lockstep member: seconds to wait for a missing sample before stepping")
      ->check(fedsim::util::kFinitePositive)
      ->capture_default_str();
  cmd->add_option("--log-level", options->log_level, "trace|debug|info|warn|error")
      ->check(CLI::IsMember({"trace", "debug", "info", "warn", "error", "critical", "off"}))
      ->capture_default_str();
  runtime::add_dds_options(*cmd, options->dds);
  cmd->callback([options] { exit_with(run_record(*options, std::cout, std::cerr)); });
}

}  // namespace

void add_topic_commands(CLI::App& app) {
  auto* topic = app.add_subcommand("topic", "inspect live DDS topics: list, echo, hz, bw, info");
  topic->require_subcommand(1);
  add_list(*topic);
  add_echo(*topic);
  add_hz(*topic);
  add_bw(*topic);
  add_info(*topic);
  add_record(app);
  add_replay_command(app);
}

}  // namespace fedsim::tools
