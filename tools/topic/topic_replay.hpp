// Replay of a recording (`fedsim record`, `fedsim run --in-process`, `fedsim-fly`) back into DDS,
// so that live displays (the instructor station's map and plots, the visual channels) show it.
//
//   Recording  reads DIR/<topic with '/' -> '_'>.csv of every catalogue topic, checks each header
//              against this build's CsvLayout of the topic type (a file of another fedsim
//              version is refused, naming the first differing column) and every cell against
//              its member's type (errors name file:line:column), and keeps the rows.
//   RowDecoder the inverse of CsvLayout::row: one row back into a DynamicData of the type. Exact:
//              flattening the decoded sample gives the same text again.
//   Replayer   merges the topics by simulation time and publishes them with a DynamicPubSubType
//              writer per topic (the topic's catalogue QoS profile, so live readers match),
//              paced against the wall clock; pause, resume and seek from any thread.
//
//   fedsim replay DIR [--speed X] [--from-s T] [--topics a,b] [--loop] [DDS options]
//
// Samples go out as recorded: nothing is re-stamped (they keep their FrameStamp). Topics
// recorded with reception time only (no simulation time) cannot be placed on the timeline and
// are not replayed; the backbone topics (tick, acknowledgement, commands, status) are replayed
// only when named in the topic list, since they would drive or command a live federation.
#pragma once

#include "common/runtime/dds_participant.hpp"
#include "common/runtime/topic_catalogue.hpp"
#include "tools/topic/csv_layout.hpp"
#include "tools/topic/dynamic_types.hpp"

#include <fastrtps/types/DynamicData.h>

#include <CLI/CLI.hpp>

#include <atomic>
#include <condition_variable>
#include <cstdint>
#include <filesystem>
#include <iosfwd>
#include <map>
#include <memory>
#include <mutex>
#include <optional>
#include <stdexcept>
#include <string>
#include <thread>
#include <vector>

namespace fedsim::tools {

/// A recording that cannot be replayed; what() names the file (and line and column).
class ReplayError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};
/// The folder is missing or holds no CSV file of a catalogue topic (`fedsim replay` exits 2).
class RecordingNotFound : public ReplayError {
 public:
  using ReplayError::ReplayError;
};
/// A cell that does not read back as its member's type; `column` indexes CsvLayout::columns().
class CellError : public std::runtime_error {
 public:
  CellError(std::size_t column, const std::string& message)
      : std::runtime_error(message), column_(column) {}
  std::size_t column() const { return column_; }

 private:
  std::size_t column_;
};

/// One CSV row of a topic type back into a DynamicData (the inverse of CsvLayout::row).
class RowDecoder {
 public:
  explicit RowDecoder(const ftypes::DynamicType_ptr& type);
  ~RowDecoder();
  RowDecoder(const RowDecoder&) = delete;
  RowDecoder& operator=(const RowDecoder&) = delete;

  const CsvLayout& layout() const { return layout_; }
  const ftypes::DynamicType_ptr& type() const { return type_; }
  /// Sets every member of `out` (a DynamicData of the type) from `cells` (one per
  /// layout().columns(), time column first). Throws CellError.
  void decode(const std::vector<std::string>& cells, ftypes::DynamicData& out) const;
  /// Checks that every cell reads back as its member's type, building nothing. Throws CellError.
  void validate(const std::vector<std::string>& cells) const;
  /// The columns of the type's top-level @key members: which instance a row is.
  const std::vector<std::size_t>& key_columns() const { return key_columns_; }

  struct Node;  // the type, compiled once (topic_replay.cpp)

 private:
  void walk(const std::vector<std::string>& cells, ftypes::DynamicData* out) const;

  ftypes::DynamicType_ptr type_;
  CsvLayout layout_;
  std::unique_ptr<Node> root_;
  std::vector<std::size_t> field_columns_;  // field i (IDL order) -> its CSV column
  std::vector<std::size_t> key_columns_;
};

/// Splits one CSV line as the recorder writes it (RFC 4180 quoting, no comments).
std::vector<std::string> split_recorded_row(const std::string& line);

struct RecordedRow {
  double time_s = 0.0;             // the time column (simulation time)
  int line = 0;                    // in the file, for messages
  std::uint32_t instance = 0;      // index of its key cells' values among the topic's instances
  std::vector<std::string> cells;  // as CsvLayout::columns()
};

struct RecordedTopic {
  const runtime::TopicInfo* info = nullptr;  // catalogue entry
  std::filesystem::path file;
  std::shared_ptr<const RowDecoder> decoder;
  std::vector<RecordedRow> rows;  // file order
  std::uint32_t instances = 0;    // distinct key values seen
};

class Recording {
 public:
  /// Loads every replayable topic of `dir` (only those in `topics` if it is not empty: each must
  /// then have its file). Throws RecordingNotFound or ReplayError.
  /// With `from_s` > 0, rows the files' indexes (recording_index.hpp) place more than a seek
  /// interval before it are not read (a seek earlier than `from_s` then finds none of them).
  static Recording load(const std::filesystem::path& dir,
                        const std::vector<std::string>& topics = {}, double from_s = 0.0);
  /// Loads one topic's file, checking its header and every row (from `from_s` as above).
  static RecordedTopic load_topic(const runtime::TopicInfo& topic,
                                  const std::filesystem::path& file, double from_s = 0.0);

  const std::filesystem::path& dir() const { return dir_; }
  const std::vector<RecordedTopic>& topics() const { return topics_; }
  /// Files found but not replayed, and why.
  const std::vector<std::string>& notes() const { return notes_; }
  std::size_t samples() const;
  /// Earliest and latest simulation time of any row (0 without rows).
  double start_s() const;
  double end_s() const;

 private:
  std::filesystem::path dir_;
  std::vector<RecordedTopic> topics_;
  std::vector<std::string> notes_;
};

struct ReplayOptions {
  double speed = 1.0;   // simulation seconds per wall-clock second; 0 = as fast as possible
  double from_s = 0.0;  // start at the first sample at/after this simulation time
  bool loop = false;    // start over at the end
};

/// Publishes a recording on DDS, paced by simulation time. Every method is thread-safe.
class Replayer {
 public:
  /// Creates one writer per topic on `dds` (the topic's catalogue QoS profile). Publishes nothing
  /// until start(). Throws std::invalid_argument for a speed outside [0, 100] or a bad from_s.
  Replayer(std::shared_ptr<runtime::DdsParticipant> dds, Recording recording,
           ReplayOptions options);
  ~Replayer();
  Replayer(const Replayer&) = delete;
  Replayer& operator=(const Replayer&) = delete;

  /// Waits (at most `timeout`) until every writer has matched a reader; false if one has not.
  bool wait_for_readers(std::chrono::milliseconds timeout) const;
  void start();
  /// Stops publishing and joins the replay thread (idempotent).
  void stop();
  /// Publication stops before pause() returns; resume() goes on from there, re-paced.
  void pause();
  void resume();
  bool paused() const;
  /// The next sample published is the first at/after `sim_time_s`; the state topics' latest
  /// sample at/before it (per instance) goes out at once, paused or not, so displays jump.
  void seek(double sim_time_s);

  /// Simulation time of the last sample published (of the seek target until one is).
  double position_s() const;
  /// True once the last sample is published (never with loop).
  bool finished() const;
  std::uint64_t published() const { return published_.load(); }
  std::uint64_t loops() const { return loops_.load(); }
  /// Why publication stopped early (a sample the writer refused); empty if it did not.
  std::string error() const;
  const Recording& recording() const { return recording_; }
  /// The numeric fields (column -> value; booleans and enums as numbers, strings and sequences
  /// left out) of the latest sample replayed on `topic`; nullopt before the first one or for a
  /// topic not replayed. For "take control from here" (a reposition to the replayed state).
  std::optional<std::map<std::string, double>> latest_fields(const std::string& topic) const;

 private:
  struct Writer;
  struct Entry {
    double time_s;
    std::uint32_t topic;
    std::uint32_t row;
  };

  void build_timeline();
  void run();
  bool wait_until_due(std::unique_lock<std::mutex>& lock);
  void apply_seek(std::unique_lock<std::mutex>& lock, double target);
  void publish(std::unique_lock<std::mutex>& lock, const Entry& entry);
  void re_anchor(double sim_time_s);

  std::shared_ptr<runtime::DdsParticipant> dds_;
  Recording recording_;
  ReplayOptions options_;
  std::vector<std::unique_ptr<Writer>> writers_;  // one per recording topic, same order
  std::vector<Entry> timeline_;                   // every row of every topic, merged by time

  mutable std::mutex mutex_;
  std::condition_variable changed_;
  std::thread thread_;
  bool started_ = false;
  bool stopping_ = false;
  bool paused_ = false;
  bool publishing_ = false;  // a sample is being written outside the lock
  bool finished_ = false;
  std::optional<double> pending_seek_;
  std::string error_;
  std::size_t next_ = 0;  // timeline index of the next sample
  double position_s_ = 0.0;
  std::chrono::steady_clock::time_point anchor_wall_;
  double anchor_sim_ = 0.0;
  std::vector<std::optional<std::uint32_t>> latest_row_;  // per topic
  std::atomic<std::uint64_t> published_{0};
  std::atomic<std::uint64_t> loops_{0};
};

struct ReplayCliOptions {
  runtime::ParticipantOptions dds;
  std::string dir;
  std::vector<std::string> topics;  // empty: every replayable topic of the folder
  double speed = 1.0;
  double from_s = 0.0;
  bool loop = false;
  double wait_s = 1.0;              // how long to wait for readers before publishing
  double progress_period_s = 2.0;
};

/// `fedsim replay`: 0 = replayed, 1 = failure, 2 = no recording at `dir` (message on `err`).
int run_replay(const ReplayCliOptions& options, std::ostream& out, std::ostream& err);
/// Adds the `replay` subcommand to `app` (as topic_commands.cpp adds `record`).
void add_replay_command(CLI::App& app);

}  // namespace fedsim::tools
