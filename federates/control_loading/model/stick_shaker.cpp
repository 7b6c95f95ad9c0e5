#include "control_loading/model/stick_shaker.hpp"

#include <cmath>
#include <stdexcept>

#include "common/units/units.hpp"

namespace fedsim::control_loading {

StickShaker::StickShaker(double alpha_on_rad, double hysteresis_rad)
    : alpha_on_rad_(alpha_on_rad), alpha_off_rad_(alpha_on_rad - hysteresis_rad) {
  if (!std::isfinite(alpha_on_rad) || !(alpha_on_rad > 0.0) || !(alpha_on_rad < units::kHalfPi)) {
    throw std::invalid_argument("StickShaker: alpha_on_rad must be in (0, pi/2)");
  }
  if (!std::isfinite(hysteresis_rad) || !(hysteresis_rad >= 0.0) ||
      !(hysteresis_rad < alpha_on_rad)) {
    throw std::invalid_argument("StickShaker: hysteresis_rad must be in [0, alpha_on_rad)");
  }
}

bool StickShaker::set_alpha_on(double alpha_on_rad) {
  const double hysteresis = alpha_on_rad_ - alpha_off_rad_;
  if (!std::isfinite(alpha_on_rad) || !(alpha_on_rad > hysteresis) || !(alpha_on_rad < units::kHalfPi)) return false;
  alpha_on_rad_ = alpha_on_rad;
  alpha_off_rad_ = alpha_on_rad - hysteresis;
  return true;
}

bool StickShaker::update(double alpha_rad) {
  if (!std::isfinite(alpha_rad)) throw std::invalid_argument("StickShaker: alpha not finite");
  const bool was_active = active_;
  active_ = active_ ? alpha_rad >= alpha_off_rad_ : alpha_rad >= alpha_on_rad_;
  if (active_ && !was_active) time_on_s_ = 0.0;
  return active_;
}

void StickShaker::advance(double h_s) {
  if (active_) time_on_s_ += h_s;
}

double StickShaker::waveform(double frequency_hz) const {
  return active_ ? std::sin(units::kTwoPi * frequency_hz * time_on_s_) : 0.0;
}

void StickShaker::reset() {
  active_ = false;
  time_on_s_ = 0.0;
}

}  // namespace fedsim::control_loading
