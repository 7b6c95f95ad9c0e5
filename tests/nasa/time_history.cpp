// Named channels sampled over time.
#include "time_history.hpp"

#include "common/csv/csv_reader.hpp"
#include "common/units/units.hpp"

#include <algorithm>
#include <cmath>
#include <fstream>
#include <stdexcept>

namespace fedsim::flight::nasa {

TimeHistory::TimeHistory(std::vector<std::string> channels)
    : names_(std::move(channels)), values_(names_.size()) {}

void TimeHistory::append(double t_s, const std::vector<double>& values) {
  if (values.size() != names_.size()) {
    throw std::invalid_argument("time history: sample has " + std::to_string(values.size()) +
                                " values for " + std::to_string(names_.size()) + " channels");
  }
  if (!times_.empty() && !(t_s > times_.back())) {
    throw std::invalid_argument("time history: times must increase (" + std::to_string(t_s) + ")");
  }
  times_.push_back(t_s);
  for (std::size_t i = 0; i < values.size(); ++i) values_[i].push_back(values[i]);
}

bool TimeHistory::has(const std::string& channel) const {
  return std::find(names_.begin(), names_.end(), channel) != names_.end();
}

std::size_t TimeHistory::index_of(const std::string& name) const {
  const auto it = std::find(names_.begin(), names_.end(), name);
  if (it == names_.end()) throw std::out_of_range("time history: no channel '" + name + "'");
  return static_cast<std::size_t>(it - names_.begin());
}

const std::vector<double>& TimeHistory::channel(const std::string& name) const {
  return values_[index_of(name)];
}

double TimeHistory::at(const std::string& channel_name, double t_s) const {
  return interpolate(channel_name, t_s, false);
}

double TimeHistory::angle_at(const std::string& channel_name, double t_s) const {
  return interpolate(channel_name, t_s, true);
}

double TimeHistory::interpolate(const std::string& channel_name, double t_s, bool is_angle) const {
  const std::vector<double>& v = channel(channel_name);
  constexpr double kTimeSlack = 1e-9;  // NASA files carry times like 0.10000000000000007
  if (times_.empty() || t_s < times_.front() - kTimeSlack || t_s > times_.back() + kTimeSlack) {
    throw std::out_of_range("time history: t = " + std::to_string(t_s) + " outside the record");
  }
  const auto upper = std::upper_bound(times_.begin(), times_.end(), t_s);
  if (upper == times_.begin()) return v.front();
  if (upper == times_.end()) return v.back();
  const std::size_t i = static_cast<std::size_t>(upper - times_.begin()) - 1;
  const double f = (t_s - times_[i]) / (times_[i + 1] - times_[i]);
  const double step = is_angle ? std::remainder(v[i + 1] - v[i], units::kTwoPi)
                              : v[i + 1] - v[i];
  return v[i] + f * step;
}

TimeHistory TimeHistory::read_csv(const std::string& path) {
  csv::CsvReader reader = csv::CsvReader::open(path);
  const auto& header = reader.header();
  if (header.front() != "time") throw csv::CsvError(path, 1, "first column must be 'time'");
  TimeHistory history(std::vector<std::string>(header.begin() + 1, header.end()));
  csv::CsvRow row;
  std::vector<double> values(header.size() - 1);
  while (reader.next(row)) {
    for (std::size_t i = 1; i < row.size(); ++i) values[i - 1] = row.number(i);
    history.append(row.number(0), values);
  }
  return history;
}

void TimeHistory::write_csv(const std::string& path) const {
  std::ofstream out(path);
  out.precision(15);
  out << "time";
  for (const std::string& name : names_) out << ',' << name;
  out << '\n';
  for (std::size_t k = 0; k < times_.size(); ++k) {
    out << times_[k];
    for (const std::vector<double>& v : values_) out << ',' << v[k];
    out << '\n';
  }
  if (!out) throw std::runtime_error("cannot write " + path);
}

}  // namespace fedsim::flight::nasa
