// The emulated A/D interface (seed 2.7.2) against hand computations: the seed's resolution
// figure, counts through the transducer, conditioning and converter, the quantisation error of
// the round trip, seeded noise, drift, and debounced discretes.
#include "io/model/adc_emulation.hpp"
#include "common/util/build_paths.hpp"
#include "io/model/input_profile.hpp"

#include "common/util/config_node.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <memory>
#include <string>

namespace fedsim::io {
namespace {

/// A control column on a 0-2 V potentiometer, gain 5 (eq 2.55: the seed's example), 10 bits
/// over 0-10 V.
AdcChannelSpec column(int bits = 10) {
  AdcChannelSpec c;
  c.name = "column";
  c.channel = Channel::kElevator;
  c.volts_at_min = 0.0;
  c.volts_at_max = 2.0;
  c.gain = 5.0;
  c.bits = bits;
  return c;
}

/// A profile source that writes one channel's value.
class Fixed final : public InputSource {
 public:
  Fixed(Channel c, double v) : channel(c), value(v) {}
  void sample(double, ControlInputs& controls) override { controls[channel] = value; }
  std::string describe() const override { return "fixed"; }
  Channel channel;
  double value;
};

TEST(AdcEmulation, TheSeedsTenBitConverterResolvesAbout10Millivolts) {
  const AdcChannelSpec c = column(10);
  // 10 V / 2^10 = 9.77 mV per count (the seed: "approximately 10 mV").
  EXPECT_EQ(c.counts(0.00976), 0);
  EXPECT_EQ(c.counts(0.00977), 1);
  EXPECT_EQ(c.counts(5.0), 512);
  EXPECT_EQ(c.counts(10.0), 1023);   // full scale clamps to the top count
  EXPECT_EQ(c.counts(-1.0), 0);
}

TEST(AdcEmulation, CountsFollowTheTransducerAndConditioningChain) {
  AdcChannelSpec c = column(12);
  // Elevator 0 (mid travel): 1 V at the wiper, x5 = 5 V, 12 bits: floor(0.5 x 4096) = 2048.
  EXPECT_DOUBLE_EQ(c.converter_volts(0.0, 0.0), 5.0);
  EXPECT_EQ(c.counts(c.converter_volts(0.0, 0.0)), 2048);
  // The seed's bias example: a transducer over 2-3 V, bias -2 V and gain 10 uses 0-10 V.
  c.volts_at_min = 2.0;
  c.volts_at_max = 3.0;
  c.bias_volts = -2.0;
  c.gain = 10.0;
  EXPECT_DOUBLE_EQ(c.converter_volts(-1.0, 0.0), 0.0);
  EXPECT_DOUBLE_EQ(c.converter_volts(1.0, 0.0), 10.0);
  EXPECT_NO_THROW(c.validate(""));
  c.bias_volts = 0.0;  // without the bias the stops lie at 20-30 V: refused, named
  try {
    c.validate("column: ");
    ADD_FAILURE() << "accepted a chain beyond the converter's range";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("column: gain/bias_volts"), std::string::npos) << e.what();
  }
}

TEST(AdcEmulation, RoundTripErrorIsWithinOneCountOfTravel) {
  for (int bits : {8, 10, 12}) {
    AdcSpec spec;
    spec.channels = {column(bits)};
    auto fixed = std::make_unique<Fixed>(Channel::kElevator, 0.0);
    Fixed* input = fixed.get();
    AdcSource adc(std::move(fixed), spec);
    // One count of the converter is 10 V / 2^bits; the column's 2 V x 5 spans the whole range,
    // so one count is 2 / 2^bits of the elevator's -1..1 travel.
    const double count = 2.0 / std::ldexp(1.0, bits);
    double worst = 0.0;
    for (int i = 0; i <= 200; ++i) {
      input->value = -1.0 + i * 0.01;
      ControlInputs in = default_controls();
      adc.sample(0.0, in);
      worst = std::max(worst, std::abs(in[Channel::kElevator] - input->value));
    }
    EXPECT_LE(worst, 1.01 * count) << bits << " bits";  // (the calibration scales by one count in 2^(bits-1))
    EXPECT_GT(worst, 0.3 * count) << bits << " bits: the quantisation must show";
  }
}

TEST(AdcEmulation, NoiseIsSeededAndDriftMovesTheReading) {
  auto run = [](std::uint64_t seed, double noise, double drift_v_per_h, double t) {
    AdcSpec spec;
    spec.seed = seed;
    spec.channels = {column(16)};
    spec.channels[0].noise_volts_rms = noise;
    spec.channels[0].drift_volts_per_hour = drift_v_per_h;
    AdcSource adc(std::make_unique<Fixed>(Channel::kElevator, 0.0), spec);
    double sum = 0.0;
    for (int i = 0; i < 50; ++i) {
      ControlInputs in = default_controls();
      adc.sample(t, in);
      sum += in[Channel::kElevator];
    }
    return sum;
  };
  EXPECT_EQ(run(1, 0.01, 0.0, 0.0), run(1, 0.01, 0.0, 0.0));  // the same seed: the same readings
  EXPECT_NE(run(1, 0.01, 0.0, 0.0), run(2, 0.01, 0.0, 0.0));  // another seed: others
  // Drift 0.1 V/h at the transducer: after an hour 0.1 V x 5 = +0.5 V at the converter, whose
  // 10 V span the elevator's 2 units of travel: +0.1 elevator.
  EXPECT_NEAR(run(1, 0.0, 0.1, 3600.0) / 50.0, 0.1, 1e-3);
  EXPECT_NEAR(run(1, 0.0, 0.1, 0.0) / 50.0, 0.0, 1e-3);
}

TEST(AdcEmulation, DiscretesChatterAndTheDebouncerGivesOneCleanChange) {
  auto transitions = [](double debounce_s) {
    AdcSpec spec;
    AdcDiscreteSpec gear;
    gear.name = "gear_lever";
    gear.channel = Channel::kGearDown;
    gear.bounce_s = 0.01;
    gear.debounce_s = debounce_s;
    spec.discretes = {gear};
    auto fixed = std::make_unique<Fixed>(Channel::kGearDown, 0.0);
    Fixed* lever = fixed.get();
    AdcSource adc(std::move(fixed), spec);
    int changes = 0;
    double last = 0.0, changed_at = -1.0;
    for (int i = 0; i < 1000; ++i) {  // 1 kHz scan, lever down at 0.1 s
      const double t = i * 0.001;
      lever->value = t >= 0.1 ? 1.0 : 0.0;
      ControlInputs in = default_controls();
      adc.sample(t, in);
      if (in[Channel::kGearDown] != last) {
        ++changes;
        if (changed_at < 0) changed_at = t;
      }
      last = in[Channel::kGearDown];
    }
    EXPECT_EQ(last, 1.0);
    return std::make_pair(changes, changed_at);
  };
  const auto clean = transitions(0.02);
  EXPECT_EQ(clean.first, 1);                 // one change...
  EXPECT_GE(clean.second, 0.1 + 0.02 - 1e-9);  // ...after the debounce time
  EXPECT_LE(clean.second, 0.1 + 0.01 + 0.02 + 0.002);
  // Negative control: without debounce the chatter comes through.
  EXPECT_GT(transitions(0.0).first, 1);
}

TEST(AdcEmulation, TheFileIsCheckedByField) {
  const std::string text = R"(fedsim_adc: 1
seed: 7
channels:
  - {name: column, channel: elevator, volts_at_min: 0, volts_at_max: 2, gain: 5, bits: 12, noise_volts_rms: 0.002}
discretes:
  - {name: gear_lever, channel: gear_down, bounce_ms: 5, debounce_ms: 20}
)";
  const AdcSpec s = AdcSpec::parse(text, "adc.yaml");
  EXPECT_EQ(s.seed, 7u);
  ASSERT_EQ(s.channels.size(), 1u);
  EXPECT_EQ(s.channels[0].bits, 12);
  EXPECT_DOUBLE_EQ(s.discretes[0].debounce_s, 0.02);
  auto expect_error = [&](const std::string& from, const std::string& to, const std::string& words) {
    std::string bad = text;
    bad.replace(bad.find(from), from.size(), to);
    try {
      AdcSpec::parse(bad, "adc.yaml");
      ADD_FAILURE() << "accepted: " << to;
    } catch (const util::ConfigError& e) {
      EXPECT_NE(std::string(e.what()).find(words), std::string::npos) << e.what();
    }
  };
  expect_error("bits: 12", "bits: 40", "bits");
  expect_error("gain: 5", "gain: 50", "gain/bias_volts");  // 2 V x 50 = 100 V: beyond 10 V
  expect_error("noise_volts_rms: 0.002", "noise_volts_rms: .inf", "noise_volts_rms");
  expect_error("channel: gear_down", "channel: elevator", "converted twice");
  expect_error("volts_at_max: 2", "volts_at_max: 0", "volts_at_max");
}

TEST(ShippedAdcFiles, TheC172InterfaceLoadsAndItsChainsFitTheirConverters) {
  const AdcSpec s = AdcSpec::load_file(fedsim::util::data_dir() + "/inceptors/adc_c172.yaml");
  ASSERT_EQ(s.channels.size(), 4u);
  for (const auto& c : s.channels) EXPECT_NO_THROW(c.validate(c.name + ": "));
  EXPECT_EQ(s.discretes.size(), 2u);
}

}  // namespace
}  // namespace fedsim::io
