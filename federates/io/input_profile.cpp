#include "io/input_profile.hpp"

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <fstream>
#include <set>
#include <sstream>

namespace fedsim::io {

namespace {

std::string trim(const std::string& s) {
  const auto first = s.find_first_not_of(" \t\r");
  if (first == std::string::npos) return "";
  const auto last = s.find_last_not_of(" \t\r");
  return s.substr(first, last - first + 1);
}

std::vector<std::string> split_fields(const std::string& line) {
  std::vector<std::string> out;
  std::stringstream in(line);
  std::string field;
  while (std::getline(in, field, ',')) out.push_back(trim(field));
  if (!line.empty() && line.back() == ',') out.emplace_back();
  return out;
}

bool parse_number(const std::string& text, double& out) {
  if (text.empty()) return false;
  char* end = nullptr;
  errno = 0;
  out = std::strtod(text.c_str(), &end);
  return errno == 0 && end == text.c_str() + text.size() && std::isfinite(out);
}

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
  InputProfile p;
  p.origin_ = origin;
  std::istringstream in(text);
  std::string raw;
  int line_no = 0;
  bool have_header = false;
  int same_time_rows = 0;
  auto fail = [&](const std::string& why) -> void {
    throw ProfileError(origin + ":" + std::to_string(line_no) + ": " + why);
  };
  std::set<Channel> driven;
  while (std::getline(in, raw)) {
    ++line_no;
    const std::string line = trim(raw.substr(0, raw.find('#')));
    if (line.empty()) continue;
    const auto fields = split_fields(line);
    if (!have_header) {
      if (fields.empty() || fields[0] != "time_s") fail("the header must start with 'time_s'");
      if (fields.size() < 2) fail("the header names no channel");
      for (std::size_t i = 1; i < fields.size(); ++i) {
        const auto channels = channels_named(fields[i]);
        if (channels.empty()) {
          fail("unknown channel '" + fields[i] + "' (known: " + join(known_channel_names()) + ")");
        }
        for (Channel c : channels) {
          if (!driven.insert(c).second) fail("channel '" + fields[i] + "' is given twice");
        }
        p.names_.push_back(fields[i]);
        p.targets_.push_back(channels);
      }
      have_header = true;
      continue;
    }
    if (fields.size() != p.names_.size() + 1) {
      fail("expected " + std::to_string(p.names_.size() + 1) + " values, found " +
           std::to_string(fields.size()));
    }
    double t = 0.0;
    if (!parse_number(fields[0], t)) fail("time_s: '" + fields[0] + "' is not a number");
    if (t < 0.0) fail("time_s must not be negative");
    if (!p.times_.empty() && t < p.times_.back()) {
      fail("time_s goes backwards (" + fields[0] + " after " + std::to_string(p.times_.back()) + ")");
    }
    same_time_rows = (!p.times_.empty() && t == p.times_.back()) ? same_time_rows + 1 : 0;
    if (same_time_rows > 1) fail("more than two rows at time " + fields[0] + " (a step needs two)");
    std::vector<double> row;
    for (std::size_t i = 1; i < fields.size(); ++i) {
      double v = 0.0;
      if (!parse_number(fields[i], v)) {
        fail(p.names_[i - 1] + ": '" + fields[i] + "' is not a number");
      }
      const auto& info = channel_info(p.targets_[i - 1].front());
      if (v < info.min || v > info.max) {
        fail(p.names_[i - 1] + ": " + fields[i] + " is outside [" + std::to_string(info.min) +
             ", " + std::to_string(info.max) + "]");
      }
      row.push_back(v);
    }
    p.times_.push_back(t);
    p.rows_.push_back(std::move(row));
  }
  if (!have_header) throw ProfileError(origin + ": empty profile (no header line)");
  if (p.rows_.empty()) throw ProfileError(origin + ": the profile has a header but no rows");
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
