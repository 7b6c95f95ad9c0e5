#include "io/model/input_profile.hpp"

#include <algorithm>
#include <cmath>
#include <fstream>
#include <set>
#include <sstream>

namespace fedsim::io {

namespace {

std::string join(const std::vector<std::string>& words) {
  std::string out;
  for (const auto& w : words) out += (out.empty() ? "" : ", ") + w;
  return out;
}

}  // namespace

InputProfile InputProfile::load_file(const std::string& path) {
  std::ifstream in(path);
  if (!in) throw ProfileError(path + ": cannot open input profile");
  std::ostringstream text;
  text << in.rdbuf();
  return parse(text.str(), path);
}

InputProfile InputProfile::parse(const std::string& text, const std::string& origin) {
  try {
    std::istringstream in(text);
    csv::CsvReader reader(in, origin);
    return parse(reader);
  } catch (const csv::CsvError& e) {
    throw ProfileError(e.what());
  }
}

InputProfile InputProfile::parse(csv::CsvReader& reader) {
  InputProfile p;
  p.origin_ = reader.origin();
  const auto& header = reader.header();
  auto header_error = [&](const std::string& why) {
    throw csv::CsvError(reader.origin(), reader.line(), why);
  };
  if (header.empty() || header[0] != "time_s") header_error("the header must start with 'time_s'");
  if (header.size() < 2) header_error("the header names no channel");
  std::set<Channel> driven;
  for (std::size_t i = 1; i < header.size(); ++i) {
    const auto channels = channels_named(header[i]);
    if (channels.empty()) {
      header_error("unknown channel '" + header[i] + "' (known: " + join(known_channel_names()) +
                   ")");
    }
    for (Channel c : channels) {
      if (!driven.insert(c).second) header_error("channel '" + header[i] + "' is given twice");
    }
    p.names_.push_back(header[i]);
    p.targets_.push_back(channels);
  }
  int same_time_rows = 0;
  csv::CsvRow row;
  while (reader.next(row)) {
    const double t = row.number(0);
    if (t < 0.0) row.fail("time_s must not be negative");
    if (!p.times_.empty() && t < p.times_.back()) {
      row.fail("time_s goes backwards (" + row.text(0) + " after " +
               std::to_string(p.times_.back()) + ")");
    }
    same_time_rows = (!p.times_.empty() && t == p.times_.back()) ? same_time_rows + 1 : 0;
    if (same_time_rows > 1) row.fail("more than two rows at time " + row.text(0) + " (a step needs two)");
    std::vector<double> values;
    for (std::size_t i = 1; i < row.size(); ++i) {
      const auto& info = channel_info(p.targets_[i - 1].front());
      values.push_back(row.number_in(p.names_[i - 1], info.min, info.max));
    }
    p.times_.push_back(t);
    p.rows_.push_back(std::move(values));
  }
  if (p.rows_.empty()) throw csv::CsvError(reader.origin(), 0, "the profile has a header but no rows");
  return p;
}

double InputProfile::value(std::size_t column, double t) const {
  const std::size_t n = times_.size();
  if (t <= times_.front()) return rows_.front()[column];
  // Search from the cursor: time normally moves forward a frame at a time.
  if (cursor_ >= n || times_[cursor_] > t) cursor_ = 0;
  while (cursor_ + 1 < n && times_[cursor_ + 1] <= t) ++cursor_;
  const std::size_t i = cursor_;
  if (i + 1 >= n) return rows_.back()[column];
  const double f = (t - times_[i]) / (times_[i + 1] - times_[i]);
  return rows_[i][column] * (1.0 - f) + rows_[i + 1][column] * f;
}

void InputProfile::sample(double sim_time_s, ControlInputs& controls) {
  for (std::size_t c = 0; c < names_.size(); ++c) {
    const double v = value(c, sim_time_s);
    for (Channel ch : targets_[c]) controls[ch] = v;
  }
}

void InputProfile::sample_relative(double sim_time_s, const ControlInputs& base,
                                   ControlInputs& out) const {
  out = base;
  for (std::size_t c = 0; c < names_.size(); ++c) {
    const double v = value(c, sim_time_s);
    for (Channel ch : targets_[c]) out[ch] = base[ch] + v;
  }
  out.clamp();
}

bool InputProfile::drives(Channel channel) const {
  for (const auto& t : targets_) {
    if (std::find(t.begin(), t.end(), channel) != t.end()) return true;
  }
  return false;
}

std::string InputProfile::describe() const {
  std::ostringstream out;
  out << "profile " << origin_ << " (" << join(names_) << "; " << times_.front() << "-"
      << times_.back() << " s)";
  return out.str();
}

}  // namespace fedsim::io
