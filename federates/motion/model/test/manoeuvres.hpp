// Synthetic "recorded-style" manoeuvres for the motion tests: the specific force at the pilot's
// head and the body rates a flight model would publish, frame by frame.
//   Pitch doublet: pitch-rate command +q then -q for 2 s each (from t = 2 s), through the
//     short-period lag (0.4 s); theta = integral q; f_x = g sin(theta),
//     f_z = -g cos(theta) - V q (the pull-up's normal acceleration).
//   Takeoff roll: thrust builds up over 2 s to a longitudinal acceleration a, held for the
//     roll, seeded runway roughness on f_z (0.3 m/s^2 rms, lag 0.05 s); rotation at 30 s at
//     3 deg/s for 3 s (at 75 m/s: f_z = -g cos(theta) - 75 q); afterwards
//     f_x = g sin(theta) + 0.5 m/s^2 (still accelerating).
#pragma once

#include <cmath>
#include <random>
#include <vector>

#include "common/units/units.hpp"
#include "motion/model/motion_platform.hpp"

namespace fedsim::motion::test {

inline constexpr double kG = 9.80665;

struct ManoeuvreScale {
  double pitch_rate_radps = 6.0 * units::kDegToRad;  // doublet amplitude
  double airspeed_mps = 70.0;
  double takeoff_acceleration_mps2 = 2.5;
};

inline std::vector<MotionInputs> pitch_doublet(double dt_s, double duration_s,
                                               const ManoeuvreScale& scale = {}) {
  std::vector<MotionInputs> inputs;
  double q = 0.0;
  double theta = 0.0;
  const double lag = std::exp(-dt_s / 0.4);
  for (int n = 0; n * dt_s < duration_s; ++n) {
    const double t = n * dt_s;
    const double q_cmd = (t >= 2.0 && t < 4.0)   ? scale.pitch_rate_radps
                         : (t >= 4.0 && t < 6.0) ? -scale.pitch_rate_radps
                                                 : 0.0;
    q = lag * q + (1.0 - lag) * q_cmd;
    theta += q * dt_s;
    MotionInputs in;
    in.specific_force_eye_body_mps2 = {kG * std::sin(theta), 0.0,
                                       -kG * std::cos(theta) - scale.airspeed_mps * q};
    in.omega_body_radps = {0.0, q, 0.0};
    inputs.push_back(in);
  }
  return inputs;
}

inline std::vector<MotionInputs> takeoff_roll(double dt_s, double duration_s,
                                              const ManoeuvreScale& scale = {}, unsigned seed = 7) {
  std::vector<MotionInputs> inputs;
  std::mt19937_64 rng(seed);
  std::normal_distribution<double> roughness(0.0, 0.3);
  double bump = 0.0;
  const double bump_lag = std::exp(-dt_s / 0.05);
  double q = 0.0;
  double theta = 0.0;
  const double lag = std::exp(-dt_s / 0.4);
  const double a = scale.takeoff_acceleration_mps2;
  for (int n = 0; n * dt_s < duration_s; ++n) {
    const double t = n * dt_s;
    const double q_cmd = (t >= 30.0 && t < 33.0) ? 3.0 * units::kDegToRad : 0.0;
    q = lag * q + (1.0 - lag) * q_cmd;
    theta += q * dt_s;
    const bool rolling = t < 31.0;
    bump = bump_lag * bump + (1.0 - bump_lag) * (rolling ? roughness(rng) : 0.0);
    const double f_x = t < 2.0 ? a * t / 2.0 : (rolling ? a : kG * std::sin(theta) + 0.5);
    MotionInputs in;
    in.specific_force_eye_body_mps2 = {f_x, 0.0, -kG * std::cos(theta) - 75.0 * q + bump};
    in.omega_body_radps = {0.0, q, 0.0};
    inputs.push_back(in);
  }
  return inputs;
}

}  // namespace fedsim::motion::test
