// Envelope comparison of a fedsim run with the NASA check-case answers.
#include "envelope_comparator.hpp"

#include <algorithm>
#include <cmath>

#include "nasa_channels.hpp"

namespace fedsim::flight::nasa {

ChannelComparison EnvelopeComparator::compare(const TimeHistory& fedsim, const std::string& channel,
                                              const std::string& group, bool is_angle,
                                              double margin) const {
  ChannelComparison result;
  result.channel = channel;
  result.group = group;
  result.margin = margin;
  result.reference_samples = static_cast<int>(reference_.times().size());
  if (!fedsim.has(channel) || fedsim.empty()) return result;
  const double t_first = fedsim.times().front() - 1e-9;
  const double t_last = fedsim.times().back() + 1e-9;
  for (double t : reference_.times()) {
    if (t < t_first || t > t_last) continue;
    const double value = is_angle ? fedsim.angle_at(channel, t) : fedsim.at(channel, t);
    const Envelope e = reference_.envelope(channel, t, is_angle, value);
    if (e.runs == 0) continue;
    const double excess = std::max({0.0, value - e.high, e.low - value});
    if (excess > result.max_excess) {
      result.max_excess = excess;
      result.time_of_max_excess = t;
    }
    result.max_envelope_width = std::max(result.max_envelope_width, e.high - e.low);
    result.max_distance_to_middle =
        std::max(result.max_distance_to_middle, std::abs(value - 0.5 * (e.low + e.high)));
    result.runs = e.runs;
    ++result.samples;
  }
  return result;
}

std::vector<ChannelComparison> EnvelopeComparator::compare_all(
    const TimeHistory& fedsim, const std::map<std::string, double>& margins) const {
  std::vector<ChannelComparison> results;
  for (const Channel& c : kChannels) {
    const std::string name(c.name);
    const std::string group(c.group);
    const auto margin = margins.find(group);
    ChannelComparison r =
        compare(fedsim, name, group, c.is_angle, margin == margins.end() ? 0.0 : margin->second);
    if (r.samples > 0) results.push_back(r);
  }
  return results;
}

}  // namespace fedsim::flight::nasa
