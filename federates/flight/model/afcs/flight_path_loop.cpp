#include "flight/model/afcs/flight_path_loop.hpp"

#include <algorithm>
#include <cmath>

namespace fedsim::flight::afcs {

double flight_path_angle_rad(double vertical_speed_mps, double ground_speed_mps) {
  if (ground_speed_mps < 1.0) return 0.0;
  return std::atan2(vertical_speed_mps, ground_speed_mps);
}

namespace {
control::PidParameters path_pid(const FlightPathGains& g) {
  return control::pi_parameters(g.proportional_gain, g.integral_gain_per_s, g.pitch_min_rad,
                                g.pitch_max_rad);
}
}  // namespace

FlightPathLoop::FlightPathLoop(const FlightPathGains& gains, double dt_s)
    : gains_(gains), pid_(path_pid(gains), dt_s) {}

double FlightPathLoop::turn_compensation_rad(double bank_rad, double schedule, double alpha_rad) const {
  const double c = std::max(std::cos(bank_rad), 0.5);  // at most n = 2 worth
  return (1.0 - c) * std::max(schedule * gains_.turn_compensation_rad - alpha_rad, 0.0);
}

void FlightPathLoop::engage(double pitch_command_rad, double path_error_rad, double bank_rad,
                            double schedule, double alpha_rad) {
  const double pid_output = std::clamp(pitch_command_rad - turn_compensation_rad(bank_rad, schedule, alpha_rad),
                                       gains_.pitch_min_rad, gains_.pitch_max_rad);
  pid_.engage(path_error_rad, pid_output);
  pitch_command_rad_ = pitch_command_rad;
}

double FlightPathLoop::step(double path_command_rad, double path_rad, double bank_rad,
                            double pitch_max_rad, double schedule, double alpha_rad, double feedforward_rad) {
  const double theta = pid_.step(path_command_rad - path_rad) +
                       turn_compensation_rad(bank_rad, schedule, alpha_rad) + feedforward_rad;
  pitch_command_rad_ = std::clamp(theta, gains_.pitch_min_rad, std::min(gains_.pitch_max_rad, pitch_max_rad));
  return pitch_command_rad_;
}

}  // namespace fedsim::flight::afcs
