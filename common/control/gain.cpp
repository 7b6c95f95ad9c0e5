#include "common/control/gain.hpp"

#include "common/control/parameter_checks.hpp"

namespace fedsim::control {

Gain::Gain(double gain) : gain_(gain) { require_finite("Gain", "gain", gain); }

double Gain::step(double u) {
  require_finite_input("Gain", u);
  output_ = gain_ * u;
  return output_;
}

void Gain::reset(double output) {
  require_finite("Gain::reset", "output", output);
  output_ = output;
}

void Gain::set_gain(double gain) {
  require_finite("Gain::set_gain", "gain", gain);
  gain_ = gain;
}

}  // namespace fedsim::control
