// Calibration of real inceptors (joysticks, yokes, pedals, throttle quadrants, A/D channels):
// how a device's raw reading becomes a control channel's value, and how a switch's contact
// becomes a discrete (seed 2.7.2). Pure: no device access; the evdev source and the A/D
// emulation both feed raw readings through it.
//
// Axis: raw reading r (device units: evdev ABS counts, A/D counts) -> channel value.
//   Bipolar channels (a symmetric range: elevator, aileron, rudder, trims, steering -1..1, the
//   force sensors -1500..1500 N):
//     x = (r - centre)/(max - centre) above the centre, (r - centre)/(centre - min) below,
//   unipolar channels (0..1 and the others: throttle, brakes, flaps...):
//     x = (r - min)/(max - min),
//   then clamped to the travel, reversed (x -> -x, or 1 - x), a dead zone d around the centre
//   (bipolar) or at the low stop (unipolar): |x| < d -> 0, else sign(x)(|x| - d)/(1 - d), the
//   expo curve y = (1 - e) x + e x^3 (the radio-control "expo": finer near the centre, full
//   travel kept), scaled into the channel's range (x max, or min + x (max - min)), and snapped to the nearest detent within
//   `detent_capture` (flap and gear levers).
// Discrete: a contact (pressed = 1) -> the channel's 0/1, inverted if asked, debounced: a new
//   level is taken only once it has held for debounce_s (contact bounce lasts a few ms).
#pragma once

#include "io/model/control_inputs.hpp"

#include <cstdint>
#include <string>
#include <vector>

namespace fedsim::util {
class ConfigNode;
}

namespace fedsim::io {

struct AxisCalibration {
  std::string source;       ///< the device axis, e.g. "ABS_Y" (evdev) or an A/D channel name
  Channel channel = Channel::kElevator;
  double raw_min = 0.0;     ///< reading at the low stop
  double raw_centre = 0.0;  ///< reading at rest (bipolar channels; ignored for unipolar)
  double raw_max = 1.0;     ///< reading at the high stop, > raw_min
  bool reversed = false;
  double dead_zone = 0.0;   ///< fraction of the (half) travel, [0, 0.5)
  double expo = 0.0;        ///< [0, 1]
  std::vector<double> detents;  ///< channel values the lever snaps to (strictly increasing)
  double detent_capture = 0.0;  ///< channel units, >= 0

  /// Throws std::invalid_argument naming the field (prefixed with `where`).
  void validate(const std::string& where) const;
};

/// True for channels with a symmetric range (-1..1, +-1500 N): a centre at rest.
bool bipolar(Channel channel);

/// The channel value for raw reading `raw` (NaN in: the channel's neutral value out, and
/// reported by the caller). Within the channel's range.
double calibrate_axis(const AxisCalibration& axis, double raw);

enum class DiscreteMode : std::uint8_t {
  kMomentary,  ///< the channel follows the contact (buttons, held switches)
  kToggle,     ///< each press flips the channel (a gear lever on a joystick button)
};

struct DiscreteCalibration {
  std::string source;  ///< e.g. "BTN_TRIGGER"
  Channel channel = Channel::kApDisconnect;
  DiscreteMode mode = DiscreteMode::kMomentary;
  bool inverted = false;    ///< a contact that opens when pressed
  double debounce_s = 0.02; ///< [0, 1]
  void validate(const std::string& where) const;
};

/// A debounced contact: the reported level changes once the raw level has stayed different for
/// debounce_s.
class Debouncer {
 public:
  explicit Debouncer(double debounce_s = 0.02) : debounce_s_(debounce_s) {}
  /// The contact read `raw` at time `time_s` (non-decreasing); returns the debounced level.
  bool update(double time_s, bool raw);
  bool level() const { return level_; }

 private:
  double debounce_s_;
  bool level_ = false;
  bool pending_ = false;
  double pending_since_s_ = 0.0;
};

/// A calibration file (data/inceptors/README.md): the device it was made for and its axes and
/// discretes.
struct InceptorCalibration {
  std::string device_name;  ///< matched against the device's name ("" = any device given by path)
  std::vector<AxisCalibration> axes;
  std::vector<DiscreteCalibration> discretes;

  /// Throws util::ConfigError naming file, line and field.
  static InceptorCalibration load_file(const std::string& path);
  static InceptorCalibration parse(const std::string& text, const std::string& origin);
  /// YAML text that parse() reads back to the same calibration.
  std::string to_yaml() const;
};

/// The channel named `name` (one channel, not a group); throws std::invalid_argument listing
/// the known names.
Channel channel_called(const std::string& name);

/// For the file readers (calibration, A/D): the channel `node`'s key "channel" names, and a
/// check that no channel appears twice ("channel X is <verb> twice"); both throw
/// util::ConfigError naming file, line and field.
Channel read_channel_field(const util::ConfigNode& node);
void require_distinct_channels(const util::ConfigNode& root, const std::vector<Channel>& channels,
                               const std::string& verb);

}  // namespace fedsim::io
