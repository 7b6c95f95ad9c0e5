// Records one topic to one CSV file: the reader's listener turns each sample into a CSV line and
// queues it (on_sample); drain() writes the queue to the file (from the recorder's loop, or from
// the federate's step in a lockstep run, so a frame is acknowledged only once its samples are
// written). close() then drain() at stop loses nothing that was received. flush() also rewrites
// the file's index (`<stem>.index.json`, recording_index.hpp): rows, time span, seek table.
#pragma once

#include "tools/topic/csv_layout.hpp"
#include "tools/topic/dynamic_reader.hpp"
#include "tools/topic/recording_index.hpp"

#include <atomic>
#include <filesystem>
#include <fstream>
#include <functional>
#include <memory>
#include <mutex>
#include <optional>
#include <string>
#include <vector>

namespace fedsim::tools {

class TopicRecorder {
 public:
  /// Opens (truncates) `file` and writes the header.
  TopicRecorder(const std::string& topic, ftypes::DynamicType_ptr type,
                const std::filesystem::path& file);
  ~TopicRecorder();

  /// Subscribes on `dds` with `qos`; `on_frame` (may be empty) gets each sample's frame number
  /// after the sample is queued (the lockstep input of a recording federate).
  void subscribe(std::shared_ptr<runtime::DdsParticipant> dds, const fdds::DataReaderQos& qos,
                 std::function<void(std::uint64_t)> on_frame);
  /// Stops the reader: no sample is queued after this returns.
  void close();

  /// Formats and queues one sample (listener thread); returns its frame if the type has one.
  std::optional<std::uint64_t> on_sample(ftypes::DynamicData& sample, double receive_time_s);
  /// Writes every queued line; returns how many.
  std::size_t drain();
  /// Flushes the file and writes its index.
  void flush();

  const std::string& topic() const { return topic_; }
  const std::filesystem::path& file() const { return path_; }
  const CsvLayout& layout() const { return layout_; }
  std::uint64_t written() const { return written_.load(); }
  /// Writers matched by the reader (0 before subscribe); any thread.
  int matched_writers() const {
    const DynamicReader* reader = reader_ptr_.load();
    return reader ? reader->matched_writers() : 0;
  }

 private:
  std::optional<double> row_sim_time(const std::string& line) const;

  std::string topic_;
  ftypes::DynamicType_ptr type_;
  CsvLayout layout_;
  std::filesystem::path path_;
  std::mutex file_mutex_;
  std::ofstream file_;
  std::uint64_t header_bytes_ = 0;
  std::uint64_t bytes_ = 0;  // written so far, header included: the next line's offset
  RecordingIndex index_;
  std::mutex queue_mutex_;
  std::vector<std::string> queue_;
  std::atomic<std::uint64_t> written_{0};
  std::unique_ptr<DynamicReader> reader_;
  std::atomic<const DynamicReader*> reader_ptr_{nullptr};
};

}  // namespace fedsim::tools
