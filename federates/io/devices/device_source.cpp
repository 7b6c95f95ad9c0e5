#include "io/devices/device_source.hpp"

#include <chrono>

namespace fedsim::io {

namespace {
double steady_now_s() {
  return std::chrono::duration<double>(std::chrono::steady_clock::now().time_since_epoch()).count();
}
}  // namespace

DeviceSource::DeviceSource(DeviceOpener opener, std::string what, InceptorCalibration calibration, Options options)
    : opener_(std::move(opener)), what_(std::move(what)), mapper_(std::move(calibration)), options_(std::move(options)) {
  if (!options_.now_s) options_.now_s = steady_now_s;
  readings_.reserve(256);
}

void DeviceSource::try_open(double sim_time_s) {
  const double now = options_.now_s();
  if (now < next_attempt_s_) return;
  next_attempt_s_ = now + options_.retry_interval_s;
  std::unique_ptr<EventDevice> device = opener_();
  if (!device) {
    last_problem_ = what_ + " is not there";
    return;
  }
  const std::string& wanted = mapper_.calibration().device_name;
  if (!wanted.empty() && device->name() != wanted) {
    last_problem_ = what_ + " is '" + device->name() + "', the calibration is for '" + wanted + "'";
    return;
  }
  // The state the device is in now: axes that do not move send no event.
  readings_.clear();
  for (const AxisInfo& a : device->axes()) readings_.push_back({DeviceReading::Kind::kAxis, a.source, a.value});
  for (const DeviceReading& c : device->contacts()) readings_.push_back(c);
  device_ = std::move(device);
  ++connections_;
  feed(readings_, sim_time_s);
}

void DeviceSource::feed(const std::vector<DeviceReading>& readings, double sim_time_s) {
  for (const DeviceReading& r : readings) {
    if (r.kind == DeviceReading::Kind::kAxis) {
      mapper_.axis(r.source, r.value);
    } else {
      mapper_.contact(r.source, r.value != 0.0, sim_time_s);
    }
  }
}

void DeviceSource::sample(double sim_time_s, ControlInputs& controls) {
  if (!device_) try_open(sim_time_s);
  if (device_) {
    readings_.clear();
    if (device_->poll(readings_)) {
      feed(readings_, sim_time_s);
    } else {
      last_problem_ = what_ + " (" + device_->name() + ") went away";
      device_.reset();
      ++losses_;
      next_attempt_s_ = options_.now_s() + options_.retry_interval_s;
    }
  }
  mapper_.apply(sim_time_s, controls);
}

std::string DeviceSource::describe() const {
  const InceptorCalibration& c = mapper_.calibration();
  std::string s = "device " + what_ + " (" + std::to_string(c.axes.size()) + " axes, " +
                  std::to_string(c.discretes.size()) + " discretes calibrated)";
  if (device_) s += ": '" + device_->name() + "' at " + device_->path();
  else s += ": not connected (" + last_problem_ + ")";
  return s;
}

}  // namespace fedsim::io
