#include "io/model/inceptor_calibration.hpp"

#include "common/util/config_node.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>
#include <stdexcept>

namespace fedsim::io {

namespace {

[[noreturn]] void bad(const std::string& where, const std::string& field, const std::string& rule) {
  throw std::invalid_argument(where + field + " " + rule);
}

bool finite_all(std::initializer_list<double> values) {
  return std::all_of(values.begin(), values.end(), [](double v) { return std::isfinite(v); });
}

double clamp_to_channel(Channel channel, double value) {
  const ChannelInfo& info = channel_info(channel);
  return std::clamp(value, info.min, info.max);
}

/// The raw reading as a fraction of travel: -1..1 about the centre (bipolar), 0..1 (unipolar).
double travel_fraction(const AxisCalibration& a, double raw, bool two_sided) {
  if (two_sided) {
    const double x = raw >= a.raw_centre ? (raw - a.raw_centre) / (a.raw_max - a.raw_centre)
                                         : (raw - a.raw_centre) / (a.raw_centre - a.raw_min);
    return std::clamp(x, -1.0, 1.0);
  }
  return std::clamp((raw - a.raw_min) / (a.raw_max - a.raw_min), 0.0, 1.0);
}

double dead_zone(double x, double d) {
  const double m = std::abs(x);
  if (m < d) return 0.0;
  return std::copysign((m - d) / (1.0 - d), x);
}

double snap_to_detent(const AxisCalibration& a, double value) {
  double best = value, best_distance = a.detent_capture;
  for (double d : a.detents) {
    const double distance = std::abs(value - d);
    if (distance <= best_distance) {
      best = d;
      best_distance = distance;
    }
  }
  return best;
}

}  // namespace

bool bipolar(Channel channel) {
  const ChannelInfo& info = channel_info(channel);
  return info.min == -info.max && info.max > 0.0;
}

void AxisCalibration::validate(const std::string& where) const {
  if (!finite_all({raw_min, raw_centre, raw_max})) bad(where, "raw_min/raw_centre/raw_max", "must be finite");
  if (!(raw_max > raw_min)) bad(where, "raw_max", "must be greater than raw_min");
  if (bipolar(channel) && !(raw_centre > raw_min && raw_centre < raw_max)) {
    bad(where, "raw_centre", "must lie strictly between raw_min and raw_max (a centred control)");
  }
  if (!(dead_zone >= 0.0 && dead_zone < 0.5)) bad(where, "dead_zone", "must lie in [0, 0.5)");
  if (!(expo >= 0.0 && expo <= 1.0)) bad(where, "expo", "must lie in [0, 1]");
  if (!(detent_capture >= 0.0 && std::isfinite(detent_capture))) bad(where, "detent_capture", "must be >= 0");
  const ChannelInfo& info = channel_info(channel);
  for (std::size_t i = 0; i < detents.size(); ++i) {
    if (!(detents[i] >= info.min && detents[i] <= info.max)) {
      bad(where, "detents", "must lie in the channel's range [" + std::to_string(info.min) + ", " +
                                std::to_string(info.max) + "]");
    }
    if (i > 0 && !(detents[i] > detents[i - 1])) bad(where, "detents", "must be strictly increasing");
  }
}

double calibrate_axis(const AxisCalibration& a, double raw) {
  const ChannelInfo& info = channel_info(a.channel);
  const bool two_sided = bipolar(a.channel);
  if (!std::isfinite(raw)) return two_sided ? 0.0 : info.min;
  double x = travel_fraction(a, raw, two_sided);
  if (a.reversed) x = two_sided ? -x : 1.0 - x;
  x = dead_zone(x, a.dead_zone);
  x = (1.0 - a.expo) * x + a.expo * x * x * x;
  const double value = two_sided ? x * info.max : info.min + x * (info.max - info.min);
  return clamp_to_channel(a.channel, snap_to_detent(a, value));
}

void DiscreteCalibration::validate(const std::string& where) const {
  if (!(debounce_s >= 0.0 && debounce_s <= 1.0)) bad(where, "debounce_ms", "must lie in [0, 1000]");
}

bool Debouncer::update(double time_s, bool raw) {
  if (raw == level_) {
    pending_ = false;
    return level_;
  }
  if (!pending_) {
    pending_ = true;
    pending_since_s_ = time_s;
  }
  if (time_s - pending_since_s_ >= debounce_s_) {
    level_ = raw;
    pending_ = false;
  }
  return level_;
}

Channel channel_called(const std::string& name) {
  const std::vector<Channel> found = channels_named(name);
  if (found.size() == 1) return found.front();
  std::string known;
  for (int i = 0; i < kChannelCount; ++i) {
    known += (i ? " " : "") + std::string(channel_info(static_cast<Channel>(i)).name);
  }
  throw std::invalid_argument("unknown channel '" + name + "' (one of: " + known + ")");
}

Channel read_channel_field(const util::ConfigNode& node) {
  try {
    return channel_called(node.string("channel"));
  } catch (const std::invalid_argument& e) {
    node.fail_at("channel", e.what());
  }
}

void require_distinct_channels(const util::ConfigNode& root, const std::vector<Channel>& channels,
                               const std::string& verb) {
  for (std::size_t i = 0; i < channels.size(); ++i) {
    for (std::size_t j = 0; j < i; ++j) {
      if (channels[i] == channels[j]) {
        root.fail("channel " + std::string(channel_info(channels[i]).name) + " is " + verb + " twice");
      }
    }
  }
}

namespace {

AxisCalibration read_axis(const util::ConfigNode& node) {
  node.reject_unknown_keys({"source", "channel", "raw_min", "raw_centre", "raw_max", "reversed",
                            "dead_zone", "expo", "detents", "detent_capture"});
  AxisCalibration a;
  a.source = node.string("source");
  a.channel = read_channel_field(node);
  a.raw_min = node.number("raw_min", -1e9, 1e9);
  a.raw_max = node.number("raw_max", -1e9, 1e9);
  a.raw_centre = node.number_or("raw_centre", 0.5 * (a.raw_min + a.raw_max), -1e9, 1e9);
  a.reversed = node.boolean_or("reversed", false);
  a.dead_zone = node.number_or("dead_zone", 0.0, 0.0, 0.499);
  a.expo = node.number_or("expo", 0.0, 0.0, 1.0);
  if (node.has("detents")) a.detents = node.numbers("detents");
  a.detent_capture = node.number_or("detent_capture", 0.0, 0.0, 1e9);
  try {
    a.validate("");
  } catch (const std::invalid_argument& e) {
    node.fail(e.what());
  }
  return a;
}

DiscreteCalibration read_discrete(const util::ConfigNode& node) {
  node.reject_unknown_keys({"source", "channel", "mode", "inverted", "debounce_ms"});
  DiscreteCalibration d;
  d.source = node.string("source");
  d.channel = read_channel_field(node);
  d.mode = node.choice_or("mode", {"momentary", "toggle"}, "momentary") == "toggle" ? DiscreteMode::kToggle
                                                                                     : DiscreteMode::kMomentary;
  d.inverted = node.boolean_or("inverted", false);
  d.debounce_s = node.number_or("debounce_ms", 20.0, 0.0, 1000.0) / 1000.0;
  return d;
}

InceptorCalibration read_calibration(const util::ConfigNode& root) {
  root.reject_unknown_keys({"fedsim_inceptor_calibration", "device_name", "axes", "discretes"});
  if (root.integer("fedsim_inceptor_calibration", 1, 1) != 1) root.fail_at("fedsim_inceptor_calibration", "must be 1");
  InceptorCalibration c;
  c.device_name = root.string_or("device_name", "");
  if (root.has("axes")) {
    for (const auto& item : root.child("axes").items()) c.axes.push_back(read_axis(item));
  }
  if (root.has("discretes")) {
    for (const auto& item : root.child("discretes").items()) c.discretes.push_back(read_discrete(item));
  }
  if (c.axes.empty() && c.discretes.empty()) root.fail("a calibration needs at least one axis or discrete");
  // One source drives one channel, and one channel is driven from one source.
  std::vector<std::string> sources;
  std::vector<Channel> channels;
  for (const auto& a : c.axes) {
    sources.push_back(a.source);
    channels.push_back(a.channel);
  }
  for (const auto& d : c.discretes) {
    sources.push_back(d.source);
    channels.push_back(d.channel);
  }
  for (std::size_t i = 0; i < sources.size(); ++i) {
    for (std::size_t j = 0; j < i; ++j) {
      if (sources[i] == sources[j]) root.fail("source " + sources[i] + " is mapped twice");
    }
  }
  require_distinct_channels(root, channels, "driven");
  return c;
}

}  // namespace

InceptorCalibration InceptorCalibration::load_file(const std::string& path) {
  return read_calibration(util::ConfigNode::load_file(path));
}

InceptorCalibration InceptorCalibration::parse(const std::string& text, const std::string& origin) {
  return read_calibration(util::ConfigNode::parse(text, origin));
}

std::string InceptorCalibration::to_yaml() const {
  std::ostringstream out;
  out.precision(10);
  out << "# fedsim inceptor calibration (data/inceptors/README.md), written by `fedsim io calibrate`\n";
  out << "fedsim_inceptor_calibration: 1\n";
  out << "device_name: \"" << device_name << "\"\n";
  if (!axes.empty()) out << "axes:\n";
  for (const auto& a : axes) {
    out << "  - {source: " << a.source << ", channel: " << channel_info(a.channel).name
        << ", raw_min: " << a.raw_min << ", raw_centre: " << a.raw_centre << ", raw_max: " << a.raw_max
        << ", reversed: " << (a.reversed ? "true" : "false") << ", dead_zone: " << a.dead_zone
        << ", expo: " << a.expo;
    if (!a.detents.empty()) {
      out << ", detents: [";
      for (std::size_t i = 0; i < a.detents.size(); ++i) out << (i ? ", " : "") << a.detents[i];
      out << "], detent_capture: " << a.detent_capture;
    }
    out << "}\n";
  }
  if (!discretes.empty()) out << "discretes:\n";
  for (const auto& d : discretes) {
    out << "  - {source: " << d.source << ", channel: " << channel_info(d.channel).name
        << ", mode: " << (d.mode == DiscreteMode::kToggle ? "toggle" : "momentary")
        << ", inverted: " << (d.inverted ? "true" : "false") << ", debounce_ms: " << d.debounce_s * 1000.0
        << "}\n";
  }
  return out.str();
}

}  // namespace fedsim::io
