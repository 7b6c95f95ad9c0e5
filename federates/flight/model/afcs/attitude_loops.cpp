#include "flight/model/afcs/attitude_loops.hpp"

#include <algorithm>

namespace fedsim::flight::afcs {

namespace {

control::PidParameters proportional_integral(double kp, double ki) {
  return control::pi_parameters(kp, ki, -1.0, 1.0);
}

double clamp_unit(double x) { return std::clamp(x, -1.0, 1.0); }

}  // namespace

PitchAttitudeLoop::PitchAttitudeLoop(const PitchLoopGains& gains, double dt_s)
    : gains_(gains),
      pid_(proportional_integral(gains.attitude_gain_per_rad, gains.integral_gain_per_rad_s), dt_s) {}

void PitchAttitudeLoop::engage(double elevator, double pitch_error_rad, double pitch_rate_radps,
                               double schedule) {
  // -elevator = PI - s Kq q  ->  PI output = -elevator + s Kq q.
  const double pi_output = clamp_unit(-elevator + schedule * gains_.rate_gain_per_radps * pitch_rate_radps);
  pid_.engage(schedule * pitch_error_rad, pi_output);
  elevator_ = clamp_unit(elevator);
}

double PitchAttitudeLoop::step(double pitch_command_rad, double pitch_rad, double pitch_rate_radps,
                               double schedule) {
  const double nose_up = pid_.step(schedule * (pitch_command_rad - pitch_rad)) -
                         schedule * gains_.rate_gain_per_radps * pitch_rate_radps;
  elevator_ = clamp_unit(-nose_up);
  return elevator_;
}

RollAttitudeLoop::RollAttitudeLoop(const RollLoopGains& gains, double dt_s)
    : gains_(gains),
      pid_(proportional_integral(gains.attitude_gain_per_rad, gains.integral_gain_per_rad_s), dt_s) {}

void RollAttitudeLoop::engage(double aileron, double bank_error_rad, double roll_rate_radps,
                              double schedule) {
  const double pi_output = clamp_unit(aileron + schedule * gains_.rate_gain_per_radps * roll_rate_radps);
  pid_.engage(schedule * bank_error_rad, pi_output);
  aileron_ = clamp_unit(aileron);
}

double RollAttitudeLoop::step(double bank_command_rad, double bank_rad, double roll_rate_radps,
                              double schedule) {
  aileron_ = clamp_unit(pid_.step(schedule * (bank_command_rad - bank_rad)) -
                        schedule * gains_.rate_gain_per_radps * roll_rate_radps);
  return aileron_;
}

}  // namespace fedsim::flight::afcs
