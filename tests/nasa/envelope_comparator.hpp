// Compares a fedsim time history (SI channels, however it was produced) with the envelope of the
// NASA tools' answers for a check case.
#pragma once

#include <map>
#include <string>
#include <vector>

#include "nasa_reference.hpp"
#include "time_history.hpp"

namespace fedsim::flight::nasa {

/// Result for one channel over the whole run.
struct ChannelComparison {
  std::string channel;
  std::string group;
  int samples = 0;                 // reference times compared
  int reference_samples = 0;       // reference times there are: every one must be compared
  int runs = 0;                    // NASA tools that report the channel
  double max_excess = 0.0;         // largest distance outside [low, high] (0 = always inside)
  double time_of_max_excess = 0.0;
  double max_envelope_width = 0.0; // largest NASA spread (high - low) during the run
  double max_distance_to_middle = 0.0;  // largest |fedsim - (low + high) / 2|
  double margin = 0.0;             // allowed excess
  bool passed() const {
    return samples > 0 && samples == reference_samples && max_excess <= margin;
  }
};

class EnvelopeComparator {
 public:
  explicit EnvelopeComparator(const NasaReference& reference) : reference_(reference) {}

  /// Compares at every reference sample time. A reference time outside the fedsim record, or
  /// one where no NASA tool recorded the channel, is not compared, and a comparison that
  /// missed any reference time does not pass. A channel no NASA tool recorded gives
  /// samples == 0.
  ChannelComparison compare(const TimeHistory& fedsim, const std::string& channel,
                            const std::string& group, bool is_angle, double margin) const;

  /// All channels of nasa_channels.hpp that fedsim and at least one NASA tool recorded, with
  /// the margin of each channel's group (groups missing from `margins` get margin 0).
  std::vector<ChannelComparison> compare_all(const TimeHistory& fedsim,
                                             const std::map<std::string, double>& margins) const;

 private:
  const NasaReference& reference_;
};

}  // namespace fedsim::flight::nasa
