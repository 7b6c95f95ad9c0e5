// Named channels sampled over time.
#include "time_history.hpp"

#include <algorithm>
#include <cmath>
#include <fstream>
#include <sstream>
#include <stdexcept>

namespace fedsim::flight::nasa {

namespace {
std::vector<std::string> split_csv(const std::string& line) {
  std::vector<std::string> fields;
  std::stringstream in(line);
  std::string field;
  while (std::getline(in, field, ',')) {
    if (!field.empty() && field.back() == '\r') field.pop_back();
    fields.push_back(field);
  }
  return fields;
}
}  // namespace

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
  const double step = is_angle ? std::remainder(v[i + 1] - v[i], 2.0 * 3.14159265358979323846)
                              : v[i + 1] - v[i];
  return v[i] + f * step;
}

TimeHistory TimeHistory::read_csv(const std::string& path) {
  std::ifstream in(path);
  if (!in) throw std::runtime_error("cannot open " + path);
  std::string line;
  std::getline(in, line);
  std::vector<std::string> header = split_csv(line);
  if (header.empty() || header.front() != "time") {
    throw std::runtime_error(path + ": first column must be 'time'");
  }
  TimeHistory history(std::vector<std::string>(header.begin() + 1, header.end()));
  int line_number = 1;
  while (std::getline(in, line)) {
    ++line_number;
    if (line.empty()) continue;
    const std::vector<std::string> fields = split_csv(line);
    if (fields.size() != header.size()) {
      throw std::runtime_error(path + ":" + std::to_string(line_number) + ": expected " +
                               std::to_string(header.size()) + " fields");
    }
    std::vector<double> values;
    for (std::size_t i = 1; i < fields.size(); ++i) values.push_back(std::stod(fields[i]));
    history.append(std::stod(fields[0]), values);
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
