// The index beside each recorded CSV file (`<file stem>.index.json`): what the file holds (topic,
// type, columns, rows, first and last simulation time) and a seek table, so a tool reading an
// hour-long recording can start at minute 50 without parsing the 50 minutes before it.
//
// Seek table: an entry (simulation time, row, byte offset of the row's line) for the first row
// whose time exceeds the previous entry's by the interval. Every row before an entry is earlier
// than the entry (a reset that sends the time back adds no entry until the time passes the last
// one again), so "start reading at the entry at or before T" loses no row at or after T.
#pragma once

#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

namespace fedsim::tools {

struct SeekEntry {
  double sim_time_s = 0.0;
  std::uint64_t row = 0;          // 0 = the first row after the header
  std::uint64_t byte_offset = 0;  // of the row's line from the start of the file
};

class RecordingIndex {
 public:
  /// `interval_s` of simulation time between seek entries (> 0, finite).
  explicit RecordingIndex(double interval_s = 1.0);

  /// Notes a row written at `byte_offset`; `sim_time_s` empty for a reception-time topic.
  void add_row(std::optional<double> sim_time_s, std::uint64_t byte_offset);

  std::uint64_t rows() const { return rows_; }
  const std::vector<SeekEntry>& entries() const { return entries_; }
  std::optional<double> first_sim_time_s() const { return first_; }
  std::optional<double> last_sim_time_s() const { return last_; }

  /// Where to start reading so that every row at or after `sim_time_s` is read, with at least
  /// one interval of rows before it (every instance's sample at/before it); nullopt: from the
  /// first row (the table has nothing early enough to skip to).
  std::optional<SeekEntry> start_for(double sim_time_s) const;

  /// The index file's JSON text.
  std::string to_json(const std::string& topic, const std::string& type_name,
                      const std::string& csv_file, std::uint64_t header_bytes,
                      const std::vector<std::string>& columns) const;
  /// Reads the seek table of an index file; nullopt if the file is missing. Throws
  /// std::runtime_error naming the file for a malformed one.
  static std::optional<RecordingIndex> read(const std::filesystem::path& index_file);

 private:
  double interval_s_;
  std::uint64_t rows_ = 0;
  std::optional<double> first_, last_, newest_entry_time_;
  std::vector<SeekEntry> entries_;
};

/// DIR/fedsim_aircraft_state.csv -> DIR/fedsim_aircraft_state.index.json
std::filesystem::path index_file_for(const std::filesystem::path& csv_file);

}  // namespace fedsim::tools
