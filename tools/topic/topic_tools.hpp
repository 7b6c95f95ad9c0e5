// The topic tools as functions (the CLI in topic_commands.cpp maps options onto these; tests call
// them directly). Each returns a process exit code: 0 = success, 1 = failure (message on `err`).
//
//   fedsim topic list [-v] [--wait S]
//   fedsim topic echo <topic> [--count N] [--field a.b] [--json] [--wait S] [--timeout S]
//   fedsim topic hz <topic> [--window N] [--wait S] [--duration S]
//   fedsim topic bw <topic> [--window N] [--wait S] [--duration S]
//   fedsim topic info <topic> [--wait S]
//   fedsim record --topics t1,t2 --out DIR [--duration S] [--lockstep-member] [--name recorder]
//
// All take the common DDS options (--domain, --qos-file, --participant-profile): the default
// participant profile keeps every packet on 127.0.0.1.
#pragma once

#include "common/runtime/dds_participant.hpp"

#include <cstdint>
#include <iosfwd>
#include <string>
#include <vector>

namespace fedsim::tools {

struct ListOptions {
  runtime::ParticipantOptions dds;
  double wait_s = 1.5;   // discovery time
  bool verbose = false;  // participants and QoS of every writer/reader
};

struct EchoOptions {
  runtime::ParticipantOptions dds;
  std::string topic;
  std::uint64_t count = 0;  // stop after this many samples (0 = until Ctrl-C)
  std::string field;        // print only this field ("stamp.frame", "gear[0]")
  bool json = false;        // one JSON object per line instead of YAML-like blocks
  double wait_s = 3.0;      // how long to wait for the topic to be discovered
  double timeout_s = 0.0;   // give up (exit 1) if `count` samples have not come in this time
};

struct HzOptions {
  runtime::ParticipantOptions dds;
  std::string topic;
  std::size_t window = 10000;  // samples in the sliding window
  double wait_s = 3.0;
  double duration_s = 0.0;     // stop after this many seconds (0 = until Ctrl-C)
  double report_period_s = 1.0;
};

struct BwOptions {
  runtime::ParticipantOptions dds;
  std::string topic;
  std::size_t window = 100;    // samples in the sliding window (ros2 topic bw's default)
  double wait_s = 3.0;
  double duration_s = 0.0;     // stop after this many seconds (0 = until Ctrl-C)
  double report_period_s = 1.0;
};

struct InfoOptions {
  runtime::ParticipantOptions dds;
  std::string topic;
  double wait_s = 1.5;  // discovery time: every endpoint seen in it is shown
};

struct RecordOptions {
  runtime::ParticipantOptions dds;
  std::vector<std::string> topics;
  std::string out_dir;
  double duration_s = 0.0;       // 0 = until Ctrl-C / SIGTERM (or a SHUTDOWN command in lockstep)
  bool lockstep_member = false;  // a lockstep federate: every frame's samples before acknowledging
  std::string name = "recorder";
  double wait_s = 3.0;           // discovery time for the topics' types and writer QoS
  double progress_period_s = 2.0;
  std::string reader_profile;    // force this data_reader QoS profile (default: match writers)
  // Federate settings (lockstep member only).
  std::uint64_t max_frames = 0;
  double input_timeout_s = 1.0;
  std::string sync_qos_suffix;  // lockstep member: "" (best effort) or "_reliable" tick/frame_done
  std::string log_level = "info";
};

int run_topic_list(const ListOptions& options, std::ostream& out, std::ostream& err);
int run_topic_echo(const EchoOptions& options, std::ostream& out, std::ostream& err);
int run_topic_hz(const HzOptions& options, std::ostream& out, std::ostream& err);
int run_topic_bw(const BwOptions& options, std::ostream& out, std::ostream& err);
int run_topic_info(const InfoOptions& options, std::ostream& out, std::ostream& err);
int run_record(const RecordOptions& options, std::ostream& out, std::ostream& err);

/// "fedsim/aircraft_state" -> "fedsim_aircraft_state.csv"
std::string csv_file_name(const std::string& topic);

}  // namespace fedsim::tools
