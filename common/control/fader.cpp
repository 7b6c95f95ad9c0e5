#include "common/control/fader.hpp"

#include <cmath>
#include <sstream>
#include <stdexcept>

#include "common/control/parameter_checks.hpp"

namespace fedsim::control {
namespace {

constexpr const char* kBlock = "Fader";

int checked_fade_steps(double fade_time_s, double dt_s) {
  require_positive(kBlock, "fade_time_s", fade_time_s);
  require_sample_period(kBlock, dt_s);
  require_at_least_sample_period(kBlock, "fade_time_s", fade_time_s, dt_s);
  if (fade_time_s / dt_s > 1e9) {
    std::ostringstream message;
    message.precision(9);
    message << kBlock << ": fade_time_s = " << fade_time_s << " is more than 1e9 steps of dt_s = "
            << dt_s;
    throw std::invalid_argument(message.str());
  }
  // The relative tolerance keeps a fade of exactly M periods (0.5 s at 0.01 s) at M steps.
  return static_cast<int>(std::ceil(fade_time_s / dt_s * (1.0 - 1e-12)));
}

}  // namespace

Fader::Fader(double fade_time_s, double dt_s)
    : fade_time_s_(fade_time_s), fade_steps_(checked_fade_steps(fade_time_s, dt_s)) {}

double Fader::step(int source, double input) {
  require_finite_input(kBlock, input);
  if (!started_) {
    started_ = true;
    source_ = source;
    output_ = input;
    return output_;
  }
  if (source != source_) {
    source_ = source;
    offset_ = output_ - input;
    steps_left_ = fade_steps_;
  }
  if (steps_left_ > 0) --steps_left_;
  if (steps_left_ == 0) offset_ = 0.0;
  output_ = input + offset_ * (static_cast<double>(steps_left_) / fade_steps_);
  return output_;
}

void Fader::reset(int source, double output) {
  require_finite("Fader::reset", "output", output);
  source_ = source;
  output_ = output;
  offset_ = 0.0;
  steps_left_ = 0;
  started_ = true;
}

}  // namespace fedsim::control
