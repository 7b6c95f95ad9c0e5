// A/D-converter emulation (seed 2.7.2): what a simulator's interface hardware does to a control
// position before the software sees it, so that a scripted profile (or any source) can be flown
// through the same imperfections as a cockpit's transducers.
//
// Analogue channel, per sample:
//   transducer   v = v_min + (v_max - v_min) (u - u_min)/(u_max - u_min) + drift t
//                (a potentiometer whose wiper covers part of its track; u the control's value
//                in its channel range; drift in V/h, the slow offset drift of the transducer
//                and its conditioning)
//   conditioning v_adc = gain (v + bias) + noise     (eq 2.55's gain -R2/R1 taken as its
//                magnitude, with Figure 2.22's bias compensation; noise Gaussian, V rms,
//                from a seeded generator)
//   converter    n = floor((v_adc - V_lo)/(V_hi - V_lo) 2^bits), clamped to [0, 2^bits - 1]
//                (a unipolar n-bit converter: a 10-bit one over 0-10 V resolves 9.8 mV)
// then the calibration (inceptor_calibration.hpp) turns counts into the channel value.
//
// Discrete channel: a switch that grounds a pulled-up input (Figure 2.20): closed reads 0 V,
// open 5 V; the input reads "closed" below the TTL low threshold 0.8 V and "open" above 2.0 V.
// A contact chatters for bounce_s after it changes (a seeded random level each sample), and
// the debouncer (inceptor_calibration.hpp) filters it.
//
// Deterministic: the same seed and inputs give the same counts.
#pragma once

#include "io/model/control_inputs.hpp"
#include "io/model/inceptor_calibration.hpp"
#include "io/model/input_source.hpp"

#include <cstdint>
#include <memory>
#include <random>
#include <string>
#include <vector>

namespace fedsim::io {

struct AdcChannelSpec {
  std::string name;  ///< e.g. "column_pitch"
  Channel channel = Channel::kElevator;
  double volts_at_min = 0.0;  ///< transducer output at the channel's minimum [V]
  double volts_at_max = 2.0;  ///< ... and at its maximum [V] (below volts_at_min: reversed wiring)
  double gain = 5.0;          ///< conditioning gain |R2/R1| (eq 2.55), > 0
  double bias_volts = 0.0;    ///< bias added before the gain (Figure 2.22) [V]
  int bits = 12;              ///< converter resolution, 4..24
  double range_min_volts = 0.0;   ///< converter input range [V]
  double range_max_volts = 10.0;
  double noise_volts_rms = 0.0;       ///< at the converter's input [V], >= 0
  double drift_volts_per_hour = 0.0;  ///< transducer offset drift [V/h]

  /// Throws std::invalid_argument naming the field (prefixed with `where`).
  void validate(const std::string& where) const;
  /// Volts at the converter for channel value u (no noise, drift at time t).
  double converter_volts(double u, double time_s) const;
  /// The count for `volts` at the converter.
  std::int64_t counts(double volts) const;
  /// The calibration a technician would set from the nominal chain (no drift, no noise): the
  /// counts at the channel's stops and centre.
  AxisCalibration nominal_calibration() const;
};

struct AdcDiscreteSpec {
  std::string name;  ///< e.g. "gear_lever"
  Channel channel = Channel::kGearDown;
  double bounce_s = 0.005;    ///< contact chatter after a change, [0, 1]
  double debounce_s = 0.02;   ///< the interface's debounce time, [0, 1]
  void validate(const std::string& where) const;
};

struct AdcSpec {
  std::uint64_t seed = 1;
  std::vector<AdcChannelSpec> channels;
  std::vector<AdcDiscreteSpec> discretes;
  /// YAML (data/inceptors/README.md, "A/D emulation"); throws util::ConfigError naming file,
  /// line and field.
  static AdcSpec load_file(const std::string& path);
  static AdcSpec parse(const std::string& text, const std::string& origin);
};

/// Passes another source's channels through the emulated interface: every channel the spec
/// names is converted, digitised and calibrated back; the rest pass unchanged.
class AdcSource final : public InputSource {
 public:
  AdcSource(std::unique_ptr<InputSource> inner, AdcSpec spec);
  void sample(double sim_time_s, ControlInputs& controls) override;
  std::string describe() const override;
  bool valid() const override { return inner_->valid(); }

  /// The counts of analogue channel i at the last sample.
  std::int64_t last_counts(std::size_t i) const { return counts_[i]; }

 private:
  struct DiscreteState {
    bool contact = false;   // the switch's true position (closed = on)
    double changed_s = -1e9;
    Debouncer debouncer;
  };
  bool read_contact(const AdcDiscreteSpec& spec, DiscreteState& state, double time_s, bool on);

  std::unique_ptr<InputSource> inner_;
  AdcSpec spec_;
  std::vector<AxisCalibration> calibrations_;
  std::vector<std::int64_t> counts_;
  std::vector<DiscreteState> discretes_;
  std::mt19937_64 random_;
  std::normal_distribution<double> noise_{0.0, 1.0};
};

}  // namespace fedsim::io
