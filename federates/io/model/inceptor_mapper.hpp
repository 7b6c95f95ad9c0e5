// From a device's readings to control channels through a calibration (pure: the evdev device
// layer turns kernel events into source names and values; tests feed them directly).
//
// Axes keep their latest raw reading; contacts are debounced in time and, for toggles, flip
// their channel on each debounced press. apply() writes every mapped channel.
#pragma once

#include "io/model/control_inputs.hpp"
#include "io/model/inceptor_calibration.hpp"

#include <cstdint>
#include <string>
#include <vector>

namespace fedsim::io {

class InceptorMapper {
 public:
  explicit InceptorMapper(InceptorCalibration calibration);

  /// The latest reading of axis `source` (a source not in the calibration is counted and
  /// ignored; a non-finite reading is counted and ignored, the previous one kept).
  void axis(const std::string& source, double raw);
  /// Contact `source` read pressed/released at `time_s`.
  void contact(const std::string& source, bool pressed, double time_s);
  /// Writes the mapped channels for time `time_s` (debounce clocks advance).
  void apply(double time_s, ControlInputs& controls);

  const InceptorCalibration& calibration() const { return calibration_; }
  /// Readings of sources the calibration does not name, and rejected (non-finite) ones.
  std::uint64_t unmapped_readings() const { return unmapped_; }
  std::uint64_t rejected_readings() const { return rejected_; }
  /// True once axis i has had a reading.
  bool axis_seen(std::size_t i) const { return axes_[i].seen; }

 private:
  struct AxisState {
    double raw = 0.0;
    bool seen = false;
  };
  struct ContactState {
    bool raw = false;
    Debouncer debouncer;
    bool toggled = false;
    bool was_pressed = false;
  };
  InceptorCalibration calibration_;
  std::vector<AxisState> axes_;
  std::vector<ContactState> contacts_;
  std::uint64_t unmapped_ = 0;
  std::uint64_t rejected_ = 0;
};

/// `fedsim io calibrate`'s bookkeeping: the travel each axis was moved through and where it
/// rests, made into an AxisCalibration.
class CalibrationRecorder {
 public:
  /// kernel_min/max: the range the device reports for the axis (for the "barely moved" check).
  void start(const std::string& source, Channel channel, double kernel_min, double kernel_max);
  void observe(double raw);
  /// The axis at rest reads `rest`. Throws std::runtime_error when the axis moved through less
  /// than 20 % of its kernel range (not moved to its stops), or, for a centred control, when
  /// the rest position is within 5 % of travel of a stop.
  AxisCalibration finish(double rest) const;
  double seen_min() const { return min_; }
  double seen_max() const { return max_; }

 private:
  std::string source_;
  Channel channel_ = Channel::kElevator;
  double kernel_min_ = 0.0, kernel_max_ = 1.0;
  double min_ = 0.0, max_ = 0.0;
  bool any_ = false;
};

}  // namespace fedsim::io
