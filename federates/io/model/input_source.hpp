// Where pilot inputs come from: a scripted profile (input_profile.hpp), an evdev device
// (joystick, yoke, pedals: io/devices/device_source.hpp), and the A/D emulation
// (adc_emulation.hpp), which wraps another source.
#pragma once

#include "io/model/control_inputs.hpp"

#include <memory>
#include <string>
#include <vector>

namespace fedsim::io {

struct PilotObservation;  // stall_entry_pilot.hpp: what a closed-loop source sees of the aircraft

class InputSource {
 public:
  virtual ~InputSource() = default;
  /// Writes the inputs at simulation time `sim_time_s` into `controls`. Channels the source
  /// does not drive are left as they are.
  virtual void sample(double sim_time_s, ControlInputs& controls) = 0;
  /// One line for logs, e.g. "profile doublets.csv (3 channels, 0-30 s)".
  virtual std::string describe() const = 0;
  /// False while the source has lost its device (unplugged, a read error): the controls it
  /// leaves are not the pilot's. The I/O federate then sets DISCRETE_INPUTS_INVALID and the
  /// flight federate holds the last valid controls.
  virtual bool valid() const { return true; }
  /// True for a source that flies the aircraft closed loop (a test pilot): the I/O component
  /// then reads the aircraft's state and calls observe() before each sample().
  virtual bool closed_loop() const { return false; }
  virtual void observe(const PilotObservation& /*aircraft*/) {}
};

/// Sources sampled in order, each over the channels the ones before it wrote (a profile for
/// the panel, a joystick over it for the primary controls). Valid while every layer is.
class LayeredSource final : public InputSource {
 public:
  explicit LayeredSource(std::vector<std::unique_ptr<InputSource>> layers) : layers_(std::move(layers)) {}
  void sample(double sim_time_s, ControlInputs& controls) override {
    for (auto& layer : layers_) layer->sample(sim_time_s, controls);
  }
  std::string describe() const override {
    std::string s;
    for (const auto& layer : layers_) s += (s.empty() ? "" : ", then ") + layer->describe();
    return s;
  }
  bool valid() const override {
    for (const auto& layer : layers_) {
      if (!layer->valid()) return false;
    }
    return true;
  }
  bool closed_loop() const override {
    for (const auto& layer : layers_) {
      if (layer->closed_loop()) return true;
    }
    return false;
  }
  void observe(const PilotObservation& aircraft) override {
    for (auto& layer : layers_) layer->observe(aircraft);
  }

 private:
  std::vector<std::unique_ptr<InputSource>> layers_;
};

}  // namespace fedsim::io
