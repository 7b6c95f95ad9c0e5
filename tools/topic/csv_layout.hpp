// The CSV layout of one topic type for the recorder: a time column first, then every field
// flattened in IDL order ("stamp.frame", "velocity_ned_mps[0]", "gear[3].compression_m").
// Pure (no DDS, no files): built from the DynamicType, fed with SampleNodes.
//
// Time column: "sim_time_s" from the sample's FrameStamp (member "stamp.sim_time_s") or a
// top-level "sim_time_s" field (which is then moved first rather than repeated); otherwise
// "receive_time_s", the reception time in seconds since the Unix epoch.
// Cells: numbers as the shortest text that reads back to the same value, booleans 1/0, enums as
// integers, strings quoted when they hold a comma, quote, line break or edge blank, sequences as
// one JSON-array cell.
#pragma once

#include "tools/topic/dynamic_types.hpp"
#include "tools/topic/sample_tree.hpp"

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace fedsim::tools {

class CsvLayout {
 public:
  explicit CsvLayout(const ftypes::DynamicType_ptr& type);

  /// Column names, time column first.
  const std::vector<std::string>& columns() const { return columns_; }
  /// The header line (no trailing newline).
  std::string header() const;
  /// True if the time column is simulation time from the sample (else reception time).
  bool has_sim_time() const { return time_source_ != TimeSource::Receive; }
  /// True if samples carry a frame number ("stamp.frame" or top-level "frame").
  bool has_frame() const { return frame_path_.has_value(); }

  /// The frame number of a sample (nullopt if the type has none).
  std::optional<std::uint64_t> frame_of(const SampleNode& sample) const;
  /// One CSV line (no trailing newline) for a sample received at `receive_time_s`.
  std::string row(const SampleNode& sample, double receive_time_s) const;

 private:
  enum class TimeSource { Stamp, TopLevel, Receive };
  TimeSource time_source_ = TimeSource::Receive;
  std::optional<std::vector<std::string>> frame_path_;
  std::vector<std::string> columns_;
  std::size_t field_count_ = 0;  // flattened fields (columns_ minus the time column)
  std::optional<std::size_t> moved_field_;  // index of top-level sim_time_s among the fields
};

/// Quotes a CSV cell if needed (RFC 4180: doubled quotes inside).
std::string csv_quote(const std::string& cell);
/// The flattened field names of a type, in IDL order (no time column).
std::vector<std::string> flattened_field_names(const ftypes::DynamicType_ptr& type);
/// The flattened cells of a sample, same order as flattened_field_names.
std::vector<std::string> flattened_cells(const SampleNode& sample);

}  // namespace fedsim::tools
