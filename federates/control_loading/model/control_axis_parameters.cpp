#include "control_loading/model/control_axis_parameters.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>
#include <stdexcept>
#include <string>

namespace fedsim::control_loading {
namespace {

class Checker {
 public:
  explicit Checker(std::string_view axis) : axis_(axis) {}

  void positive(const char* field, double value) const {
    if (!std::isfinite(value) || !(value > 0.0)) fail(field, value, "must be positive");
  }
  void non_negative(const char* field, double value) const {
    if (!std::isfinite(value) || !(value >= 0.0)) fail(field, value, "must not be negative");
  }
  [[noreturn]] void fail(const char* field, double value, const std::string& problem) const {
    std::ostringstream message;
    message.precision(9);
    message << "ControlAxisParameters[" << axis_ << "]: " << field << " = " << value << " "
            << problem;
    throw std::invalid_argument(message.str());
  }

 private:
  std::string_view axis_;
};

// Where the roll wheel and the pedals differ from the pitch column (the struct's defaults): the
// control and its feel, one row per axis below.
struct AxisFeel {
  double mass_kg;
  double travel_m;  // both ways (positive and negative travel) [m]
  double breakout_force_n;
  double coulomb_friction_n;
  double viscous_damping_nspm;
  double gradient_per_qbar_m;
  double gradient_min_npm;
  double gradient_max_npm;
  double trim_travel_m;
};

// clang-format off
//                           mass travel breakout coulomb  viscous gradient gradient gradient trim
//                                       force    friction damping /qbar    min      max      travel
//                           [kg] [m]    [N]      [N]      [N s/m] [m]      [N/m]    [N/m]    [m]
constexpr AxisFeel kRollFeel{2.0, 0.12,  7.0,     3.0,     12.0,   0.15,    80.0,    2000.0,  0.03};
constexpr AxisFeel kYawFeel{ 5.0, 0.10,  30.0,    12.0,    60.0,   0.8,     400.0,   8000.0,  0.04};
// clang-format on

ControlAxisParameters with_feel(const AxisFeel& feel) {
  ControlAxisParameters p;
  p.mass_kg = feel.mass_kg;
  p.positive_travel_m = feel.travel_m;
  p.negative_travel_m = feel.travel_m;
  p.breakout_force_n = feel.breakout_force_n;
  p.coulomb_friction_n = feel.coulomb_friction_n;
  p.viscous_damping_nspm = feel.viscous_damping_nspm;
  p.gradient_per_qbar_m = feel.gradient_per_qbar_m;
  p.gradient_min_npm = feel.gradient_min_npm;
  p.gradient_max_npm = feel.gradient_max_npm;
  p.trim_travel_m = feel.trim_travel_m;
  return p;
}

}  // namespace

ControlAxisParameters default_pitch_axis() {
  ControlAxisParameters p;  // the struct's defaults are the pitch column
  p.shaker_force_n = 25.0;
  return p;
}

ControlAxisParameters default_roll_axis() { return with_feel(kRollFeel); }

ControlAxisParameters default_yaw_axis() {
  ControlAxisParameters p = with_feel(kYawFeel);
  p.backdrive_force_limit_n = 250.0;  // heavier pedals need a stronger servo and loader
  p.motor_force_limit_n = 1200.0;
  return p;
}

void validate(const ControlAxisParameters& p, std::string_view axis) {
  const Checker check(axis);
  check.positive("mass_kg", p.mass_kg);
  check.positive("positive_travel_m", p.positive_travel_m);
  check.positive("negative_travel_m", p.negative_travel_m);
  check.non_negative("breakout_force_n", p.breakout_force_n);
  check.positive("breakout_width_m", p.breakout_width_m);
  check.non_negative("coulomb_friction_n", p.coulomb_friction_n);
  check.non_negative("viscous_damping_nspm", p.viscous_damping_nspm);
  check.non_negative("gradient_per_qbar_m", p.gradient_per_qbar_m);
  check.positive("gradient_min_npm", p.gradient_min_npm);
  check.positive("gradient_max_npm", p.gradient_max_npm);
  if (p.gradient_max_npm < p.gradient_min_npm) {
    check.fail("gradient_max_npm", p.gradient_max_npm, "must not be below gradient_min_npm");
  }
  check.non_negative("trim_travel_m", p.trim_travel_m);
  if (p.trim_travel_m >= std::min(p.positive_travel_m, p.negative_travel_m)) {
    check.fail("trim_travel_m", p.trim_travel_m, "must be below both travels");
  }
  check.positive("trim_rate_mps", p.trim_rate_mps);
  if (!(p.soft_stop_fraction > 0.0 && p.soft_stop_fraction < 1.0)) {
    check.fail("soft_stop_fraction", p.soft_stop_fraction, "must be in (0, 1)");
  }
  check.non_negative("soft_stop_stiffness_npm", p.soft_stop_stiffness_npm);
  check.positive("hard_stop_stiffness_npm", p.hard_stop_stiffness_npm);
  check.non_negative("hard_stop_damping_nspm", p.hard_stop_damping_nspm);
  check.positive("mechanical_stop_beyond_m", p.mechanical_stop_beyond_m);
  check.non_negative("shaker_force_n", p.shaker_force_n);
  check.positive("shaker_frequency_hz", p.shaker_frequency_hz);
  check.positive("backdrive_natural_frequency_radps", p.backdrive_natural_frequency_radps);
  check.positive("backdrive_damping_ratio", p.backdrive_damping_ratio);
  check.positive("backdrive_force_limit_n", p.backdrive_force_limit_n);
  check.positive("motor_force_limit_n", p.motor_force_limit_n);
  if (p.backdrive_force_limit_n > p.motor_force_limit_n) {
    check.fail("backdrive_force_limit_n", p.backdrive_force_limit_n,
               "must not exceed motor_force_limit_n");
  }
  if (p.breakout_force_n + p.coulomb_friction_n >= p.motor_force_limit_n) {
    check.fail("breakout_force_n", p.breakout_force_n,
               "plus coulomb_friction_n must be below motor_force_limit_n");
  }
  check.positive("velocity_trip_mps", p.velocity_trip_mps);
  check.non_negative("safe_damping_nspm", p.safe_damping_nspm);
  check.positive("stick_velocity_mps", p.stick_velocity_mps);
}

double scheduled_gradient_npm(const ControlAxisParameters& p, double qbar_pa) {
  return std::clamp(p.gradient_per_qbar_m * qbar_pa, p.gradient_min_npm, p.gradient_max_npm);
}

}  // namespace fedsim::control_loading
