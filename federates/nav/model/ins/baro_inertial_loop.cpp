// Third-order baro-inertial vertical loop.
#include "federates/nav/model/ins/baro_inertial_loop.hpp"

#include <cmath>
#include <stdexcept>
#include <string>

namespace fedsim::nav {

BaroInertialLoop::BaroInertialLoop(double time_constant_s) : time_constant_s_(time_constant_s) {
  if (!std::isfinite(time_constant_s) || time_constant_s < 1.0 || time_constant_s > 10000.0) {
    throw std::invalid_argument("BaroInertialLoop: time_constant_s = " +
                                std::to_string(time_constant_s) + " must be in [1, 10000] s");
  }
}

VerticalChannelCorrection BaroInertialLoop::step(double ins_height_m, double baro_height_m,
                                                 double gravity_mps2, double radius_m,
                                                 double dt_s) {
  if (!std::isfinite(baro_height_m) || baro_height_m < kMinHeightM ||
      baro_height_m > kMaxHeightM) {
    throw std::invalid_argument("BaroInertialLoop: baro_height_m = " +
                                std::to_string(baro_height_m) + " is not finite or out of range");
  }
  if (!std::isfinite(ins_height_m) || !std::isfinite(gravity_mps2) || gravity_mps2 <= 0.0 ||
      !std::isfinite(radius_m) || radius_m <= 0.0 || !std::isfinite(dt_s) || dt_s <= 0.0) {
    throw std::invalid_argument("BaroInertialLoop: non-finite or non-positive input");
  }
  const double tau = time_constant_s_;
  const double k1 = 3.0 / tau;
  const double k2 = 3.0 / (tau * tau) + 2.0 * gravity_mps2 / radius_m;
  const double k3 = 1.0 / (tau * tau * tau);
  const double dh = ins_height_m - baro_height_m;
  VerticalChannelCorrection correction;
  correction.height_rate_mps = -k1 * dh;
  correction.down_acceleration_mps2 = k2 * dh - bias_estimate_down_mps2_;
  bias_estimate_down_mps2_ += -k3 * dh * dt_s;
  return correction;
}

}  // namespace fedsim::nav
