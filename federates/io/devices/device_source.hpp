// An input source over a real device (io/devices/event_device.hpp) and its calibration file,
// with hot-plug: a device that goes away makes the source invalid (the I/O federate marks its
// samples DISCRETE_INPUTS_INVALID and the flight federate holds the last valid controls); the
// source retries the opener every retry interval and is valid again once the device is back.
// Channels the calibration does not map keep the values the I/O federate gives them (its
// defaults, or a profile's).
#pragma once

#include "io/devices/event_device.hpp"
#include "io/model/inceptor_mapper.hpp"
#include "io/model/input_source.hpp"

#include <cstdint>
#include <functional>
#include <memory>
#include <string>
#include <vector>

namespace fedsim::io {

class DeviceSource final : public InputSource {
 public:
  struct Options {
    double retry_interval_s = 1.0;   ///< between attempts to open a missing device
    std::function<double()> now_s;   ///< monotonic clock for the retries (default: steady_clock)
  };
  /// `what` names the device for messages ("/dev/input/event5", "name 'T.16000M'").
  DeviceSource(DeviceOpener opener, std::string what, InceptorCalibration calibration, Options options);
  DeviceSource(DeviceOpener opener, std::string what, InceptorCalibration calibration)
      : DeviceSource(std::move(opener), std::move(what), std::move(calibration), Options{}) {}

  void sample(double sim_time_s, ControlInputs& controls) override;
  std::string describe() const override;
  bool valid() const override { return device_ != nullptr; }

  /// Times the device went away, and came (back).
  std::uint64_t losses() const { return losses_; }
  std::uint64_t connections() const { return connections_; }
  /// Why the last open failed or the device was dropped ("" if it never did).
  const std::string& last_problem() const { return last_problem_; }
  const InceptorMapper& mapper() const { return mapper_; }

 private:
  void try_open(double sim_time_s);
  void feed(const std::vector<DeviceReading>& readings, double sim_time_s);

  DeviceOpener opener_;
  std::string what_;
  InceptorMapper mapper_;
  Options options_;
  std::unique_ptr<EventDevice> device_;
  std::vector<DeviceReading> readings_;
  double next_attempt_s_ = -1e300;
  std::uint64_t losses_ = 0;
  std::uint64_t connections_ = 0;
  std::string last_problem_;
};

}  // namespace fedsim::io
