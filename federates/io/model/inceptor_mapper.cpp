#include "io/model/inceptor_mapper.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace fedsim::io {

InceptorMapper::InceptorMapper(InceptorCalibration calibration) : calibration_(std::move(calibration)) {
  for (std::size_t i = 0; i < calibration_.axes.size(); ++i) {
    calibration_.axes[i].validate("axis " + calibration_.axes[i].source + ": ");
  }
  axes_.resize(calibration_.axes.size());
  for (const auto& d : calibration_.discretes) {
    d.validate("discrete " + d.source + ": ");
    ContactState c;
    c.debouncer = Debouncer(d.debounce_s);
    contacts_.push_back(c);
  }
}

void InceptorMapper::axis(const std::string& source, double raw) {
  for (std::size_t i = 0; i < axes_.size(); ++i) {
    if (calibration_.axes[i].source != source) continue;
    if (!std::isfinite(raw)) {
      ++rejected_;
      return;
    }
    axes_[i].raw = raw;
    axes_[i].seen = true;
    return;
  }
  ++unmapped_;
}

void InceptorMapper::contact(const std::string& source, bool pressed, double time_s) {
  for (std::size_t i = 0; i < contacts_.size(); ++i) {
    if (calibration_.discretes[i].source != source) continue;
    contacts_[i].raw = pressed != calibration_.discretes[i].inverted;
    contacts_[i].debouncer.update(time_s, contacts_[i].raw);
    return;
  }
  ++unmapped_;
}

void InceptorMapper::apply(double time_s, ControlInputs& controls) {
  for (std::size_t i = 0; i < axes_.size(); ++i) {
    if (axes_[i].seen) controls[calibration_.axes[i].channel] = calibrate_axis(calibration_.axes[i], axes_[i].raw);
  }
  for (std::size_t i = 0; i < contacts_.size(); ++i) {
    ContactState& c = contacts_[i];
    const bool pressed = c.debouncer.update(time_s, c.raw);
    const DiscreteCalibration& d = calibration_.discretes[i];
    if (d.mode == DiscreteMode::kToggle) {
      if (pressed && !c.was_pressed) c.toggled = !c.toggled;
      controls[d.channel] = c.toggled ? 1.0 : 0.0;
    } else {
      controls[d.channel] = pressed ? 1.0 : 0.0;
    }
    c.was_pressed = pressed;
  }
}

void CalibrationRecorder::start(const std::string& source, Channel channel, double kernel_min, double kernel_max) {
  source_ = source;
  channel_ = channel;
  kernel_min_ = kernel_min;
  kernel_max_ = kernel_max;
  any_ = false;
}

void CalibrationRecorder::observe(double raw) {
  if (!std::isfinite(raw)) return;
  if (!any_) {
    min_ = max_ = raw;
    any_ = true;
  }
  min_ = std::min(min_, raw);
  max_ = std::max(max_, raw);
}

AxisCalibration CalibrationRecorder::finish(double rest) const {
  const double kernel_span = kernel_max_ - kernel_min_;
  const double span = max_ - min_;
  if (!any_ || !(span >= 0.2 * kernel_span) || !(span > 0.0)) {
    throw std::runtime_error(source_ + " moved through " + std::to_string(any_ ? span : 0.0) + " of its " +
                             std::to_string(kernel_span) + " counts: move it to both stops");
  }
  AxisCalibration a;
  a.source = source_;
  a.channel = channel_;
  a.raw_min = min_;
  a.raw_max = max_;
  a.raw_centre = std::clamp(rest, min_, max_);
  if (bipolar(channel_) && (a.raw_centre - min_ < 0.05 * span || max_ - a.raw_centre < 0.05 * span)) {
    throw std::runtime_error(source_ + " rests at " + std::to_string(rest) + ", at a stop of " +
                             std::to_string(min_) + ".." + std::to_string(max_) +
                             ": a centred control (" + std::string(channel_info(channel_).name) +
                             ") must rest between its stops");
  }
  if (!bipolar(channel_)) a.raw_centre = 0.5 * (min_ + max_);
  return a;
}

}  // namespace fedsim::io
