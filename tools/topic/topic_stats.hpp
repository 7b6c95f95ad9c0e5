// The pure parts of `fedsim topic bw` and `fedsim topic info`: a sliding window of sample sizes
// and its statistics, and the text both commands print (no DDS here; tested directly).
#pragma once

#include "tools/topic/topic_monitor.hpp"

#include <cstdint>
#include <deque>
#include <string>

namespace fedsim::tools {

struct BandwidthStats {
  std::size_t samples = 0;       // in the window
  double span_s = 0.0;           // first sample in the window -> now
  double bytes_per_s = 0.0;
  double samples_per_s = 0.0;
  double mean_bytes = 0.0;
  std::uint64_t min_bytes = 0;
  std::uint64_t max_bytes = 0;
};

/// The last `capacity` samples (arrival time, serialized size), like `ros2 topic bw`'s window.
class BandwidthWindow {
 public:
  explicit BandwidthWindow(std::size_t capacity);
  void add(std::int64_t arrival_ns, std::uint64_t bytes);
  /// Statistics at `now_ns`: rates over the time from the window's first sample to now (so a
  /// topic that went quiet shows a falling rate). Empty window: all zero.
  BandwidthStats stats(std::int64_t now_ns) const;
  std::uint64_t total_samples() const { return total_; }

 private:
  struct Entry {
    std::int64_t arrival_ns;
    std::uint64_t bytes;
  };
  std::size_t capacity_;
  std::deque<Entry> entries_;
  std::uint64_t total_ = 0;
};

/// "1.23 KB/s from 100 samples (50.00 samples/s)\n\tsample size mean: 24.6 B min: 24 B max: 28 B\n"
/// (B, KB, MB with 1000 as the step, as ros2 topic bw).
std::string format_bandwidth(const BandwidthStats& stats);
/// 12 -> "12 B", 1234 -> "1.23 KB", 2.5e6 -> "2.50 MB".
std::string format_bytes(double bytes);

/// Why a writer and a reader do not match under the DDS request/offered rules (the writer must
/// offer at least what the reader requests: reliability, durability, deadline, liveliness kind
/// and lease; ownership kinds equal; a common data representation; same type name and
/// partitions). Empty = they match, as far as discovery data tells.
std::vector<std::string> qos_incompatibilities(const EndpointInfo& writer, const EndpointInfo& reader);

/// `fedsim topic info`: the topic's type(s) and, for every writer and reader, its participant,
/// QoS (reliability, durability, deadline, liveliness, ownership, ...), and locators; for every
/// reader, each writer it cannot match and why.
std::string format_topic_info(const TopicInfo& topic);

}  // namespace fedsim::tools
