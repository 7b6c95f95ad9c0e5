#include "io/model/adc_emulation.hpp"

#include "common/util/config_node.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace fedsim::io {

namespace {

constexpr double kSecondsPerHour = 3600.0;
// Figure 2.20's pulled-up input and TTL thresholds.
constexpr double kOpenVolts = 5.0;
constexpr double kLowThresholdVolts = 0.8;

[[noreturn]] void bad(const std::string& where, const std::string& field, const std::string& rule) {
  throw std::invalid_argument(where + field + " " + rule);
}

}  // namespace

void AdcChannelSpec::validate(const std::string& where) const {
  for (double v : {volts_at_min, volts_at_max, bias_volts, range_min_volts, range_max_volts}) {
    if (!std::isfinite(v) || std::abs(v) > 1000.0) bad(where, "volts", "must be finite, |V| <= 1000");
  }
  if (volts_at_min == volts_at_max) bad(where, "volts_at_max", "must differ from volts_at_min");
  if (!(gain > 0.0 && gain <= 1e4)) bad(where, "gain", "must lie in (0, 10000]");
  if (bits < 4 || bits > 24) bad(where, "bits", "must lie in [4, 24]");
  if (!(range_max_volts > range_min_volts)) bad(where, "range_max_volts", "must be above range_min_volts");
  if (!(noise_volts_rms >= 0.0 && noise_volts_rms <= 100.0)) bad(where, "noise_volts_rms", "must lie in [0, 100]");
  if (!(std::abs(drift_volts_per_hour) <= 100.0)) bad(where, "drift_volts_per_hour", "must lie in [-100, 100]");
  // The nominal chain must map the channel's travel inside the converter's range, or the
  // stops read the same count as beyond them.
  const ChannelInfo& info = channel_info(channel);
  for (double u : {info.min, info.max}) {
    const double v = gain * ((u == info.min ? volts_at_min : volts_at_max) + bias_volts);
    if (v < range_min_volts || v > range_max_volts) {
      bad(where, "gain/bias_volts", "put the channel's " + std::string(u == info.min ? "minimum" : "maximum") +
                                        " at " + std::to_string(v) + " V, outside the converter's range [" +
                                        std::to_string(range_min_volts) + ", " + std::to_string(range_max_volts) + "] V");
    }
  }
}

double AdcChannelSpec::converter_volts(double u, double time_s) const {
  const ChannelInfo& info = channel_info(channel);
  const double fraction = (u - info.min) / (info.max - info.min);
  const double transducer = volts_at_min + (volts_at_max - volts_at_min) * fraction +
                            drift_volts_per_hour * time_s / kSecondsPerHour;
  return gain * (transducer + bias_volts);
}

std::int64_t AdcChannelSpec::counts(double volts) const {
  const double levels = std::ldexp(1.0, bits);
  const double n = std::floor((volts - range_min_volts) / (range_max_volts - range_min_volts) * levels);
  return static_cast<std::int64_t>(std::clamp(n, 0.0, levels - 1.0));
}

AxisCalibration AdcChannelSpec::nominal_calibration() const {
  const ChannelInfo& info = channel_info(channel);
  AxisCalibration a;
  a.source = name;
  a.channel = channel;
  const double at_min = static_cast<double>(counts(converter_volts(info.min, 0.0)));
  const double at_max = static_cast<double>(counts(converter_volts(info.max, 0.0)));
  a.reversed = at_max < at_min;
  a.raw_min = std::min(at_min, at_max);
  a.raw_max = std::max(at_min, at_max);
  a.raw_centre = static_cast<double>(counts(converter_volts(0.5 * (info.min + info.max), 0.0)));
  return a;
}

void AdcDiscreteSpec::validate(const std::string& where) const {
  if (!(bounce_s >= 0.0 && bounce_s <= 1.0)) bad(where, "bounce_ms", "must lie in [0, 1000]");
  if (!(debounce_s >= 0.0 && debounce_s <= 1.0)) bad(where, "debounce_ms", "must lie in [0, 1000]");
}

namespace {

AdcChannelSpec read_adc_channel(const util::ConfigNode& node) {
  node.reject_unknown_keys({"name", "channel", "volts_at_min", "volts_at_max", "gain", "bias_volts", "bits",
                            "range_min_volts", "range_max_volts", "noise_volts_rms", "drift_volts_per_hour"});
  AdcChannelSpec c;
  c.name = node.string("name");
  c.channel = read_channel_field(node);
  c.volts_at_min = node.number("volts_at_min", -1000.0, 1000.0);
  c.volts_at_max = node.number("volts_at_max", -1000.0, 1000.0);
  c.gain = node.number_or("gain", 1.0, 1e-6, 1e4);
  c.bias_volts = node.number_or("bias_volts", 0.0, -1000.0, 1000.0);
  c.bits = node.integer_or("bits", 12, 4, 24);
  c.range_min_volts = node.number_or("range_min_volts", 0.0, -1000.0, 1000.0);
  c.range_max_volts = node.number_or("range_max_volts", 10.0, -1000.0, 1000.0);
  c.noise_volts_rms = node.number_or("noise_volts_rms", 0.0, 0.0, 100.0);
  c.drift_volts_per_hour = node.number_or("drift_volts_per_hour", 0.0, -100.0, 100.0);
  try {
    c.validate("");
  } catch (const std::invalid_argument& e) {
    node.fail(e.what());
  }
  return c;
}

AdcDiscreteSpec read_adc_discrete(const util::ConfigNode& node) {
  node.reject_unknown_keys({"name", "channel", "bounce_ms", "debounce_ms"});
  AdcDiscreteSpec d;
  d.name = node.string("name");
  d.channel = read_channel_field(node);
  d.bounce_s = node.number_or("bounce_ms", 5.0, 0.0, 1000.0) / 1000.0;
  d.debounce_s = node.number_or("debounce_ms", 20.0, 0.0, 1000.0) / 1000.0;
  return d;
}

AdcSpec read_adc(const util::ConfigNode& root) {
  root.reject_unknown_keys({"fedsim_adc", "seed", "channels", "discretes"});
  if (root.integer("fedsim_adc", 1, 1) != 1) root.fail_at("fedsim_adc", "must be 1");
  AdcSpec s;
  s.seed = static_cast<std::uint64_t>(root.integer_or("seed", 1, 0));
  if (root.has("channels")) {
    for (const auto& item : root.child("channels").items()) s.channels.push_back(read_adc_channel(item));
  }
  if (root.has("discretes")) {
    for (const auto& item : root.child("discretes").items()) s.discretes.push_back(read_adc_discrete(item));
  }
  if (s.channels.empty() && s.discretes.empty()) root.fail("an A/D emulation needs at least one channel or discrete");
  std::vector<Channel> seen;
  for (const auto& c : s.channels) seen.push_back(c.channel);
  for (const auto& d : s.discretes) seen.push_back(d.channel);
  require_distinct_channels(root, seen, "converted");
  return s;
}

}  // namespace

AdcSpec AdcSpec::load_file(const std::string& path) { return read_adc(util::ConfigNode::load_file(path)); }

AdcSpec AdcSpec::parse(const std::string& text, const std::string& origin) {
  return read_adc(util::ConfigNode::parse(text, origin));
}

AdcSource::AdcSource(std::unique_ptr<InputSource> inner, AdcSpec spec)
    : inner_(std::move(inner)), spec_(std::move(spec)), random_(spec_.seed) {
  for (std::size_t i = 0; i < spec_.channels.size(); ++i) {
    spec_.channels[i].validate("A/D channel " + spec_.channels[i].name + ": ");
    calibrations_.push_back(spec_.channels[i].nominal_calibration());
  }
  for (const auto& d : spec_.discretes) {
    d.validate("A/D discrete " + d.name + ": ");
    DiscreteState state;
    state.debouncer = Debouncer(d.debounce_s);
    discretes_.push_back(state);
  }
  counts_.assign(spec_.channels.size(), 0);
}

bool AdcSource::read_contact(const AdcDiscreteSpec& spec, DiscreteState& state, double time_s, bool on) {
  if (on != state.contact) {
    state.contact = on;
    state.changed_s = time_s;
  }
  bool closed = state.contact;
  if (time_s - state.changed_s < spec.bounce_s) closed = (random_() & 1u) != 0;  // chatter
  const double volts = closed ? 0.0 : kOpenVolts;  // the closed switch grounds the input
  return state.debouncer.update(time_s, volts < kLowThresholdVolts);
}

void AdcSource::sample(double sim_time_s, ControlInputs& controls) {
  inner_->sample(sim_time_s, controls);
  for (std::size_t i = 0; i < spec_.channels.size(); ++i) {
    const AdcChannelSpec& c = spec_.channels[i];
    double volts = c.converter_volts(controls[c.channel], sim_time_s);
    if (c.noise_volts_rms > 0.0) volts += c.noise_volts_rms * noise_(random_);
    counts_[i] = c.counts(volts);
    controls[c.channel] = calibrate_axis(calibrations_[i], static_cast<double>(counts_[i]));
  }
  for (std::size_t i = 0; i < spec_.discretes.size(); ++i) {
    const AdcDiscreteSpec& d = spec_.discretes[i];
    controls[d.channel] = read_contact(d, discretes_[i], sim_time_s, controls[d.channel] >= 0.5) ? 1.0 : 0.0;
  }
}

std::string AdcSource::describe() const {
  return inner_->describe() + " through an emulated A/D interface (" + std::to_string(spec_.channels.size()) +
         " analogue, " + std::to_string(spec_.discretes.size()) + " discrete channels, seed " +
         std::to_string(spec_.seed) + ")";
}

}  // namespace fedsim::io
