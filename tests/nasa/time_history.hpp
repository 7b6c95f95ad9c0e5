// Named channels sampled over time, with linear interpolation; the common currency of the NASA
// check-case comparison (SI units, channel names listed in nasa_channels.hpp).
#pragma once

#include <string>
#include <vector>

namespace fedsim::flight::nasa {

class TimeHistory {
 public:
  TimeHistory() = default;
  explicit TimeHistory(std::vector<std::string> channels);

  /// Appends one sample; `values` are in channel order. Times must increase strictly.
  void append(double t_s, const std::vector<double>& values);

  bool has(const std::string& channel) const;
  const std::vector<std::string>& channels() const { return names_; }
  const std::vector<double>& times() const { return times_; }
  const std::vector<double>& channel(const std::string& name) const;
  bool empty() const { return times_.empty(); }

  /// Linear interpolation in time; throws std::out_of_range outside the sampled interval.
  double at(const std::string& channel, double t_s) const;
  /// As at(), for an angle in radians: interpolates the shorter way round the circle.
  double angle_at(const std::string& channel, double t_s) const;

  /// CSV with a "time" column first and one column per channel.
  static TimeHistory read_csv(const std::string& path);
  void write_csv(const std::string& path) const;

 private:
  std::size_t index_of(const std::string& name) const;
  double interpolate(const std::string& channel, double t_s, bool is_angle) const;

  std::vector<std::string> names_;
  std::vector<double> times_;
  std::vector<std::vector<double>> values_;  // values_[channel][sample]
};

}  // namespace fedsim::flight::nasa
