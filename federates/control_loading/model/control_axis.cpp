#include "control_loading/model/control_axis.hpp"

#include <algorithm>
#include <cmath>

namespace fedsim::control_loading {
namespace {

constexpr double kBackdriveIntegralTimeS = 0.15;

double sign(double value) { return value > 0.0 ? 1.0 : (value < 0.0 ? -1.0 : 0.0); }

}  // namespace

ControlAxis::ControlAxis(const ControlAxisParameters& parameters, const char* axis)
    : parameters_(parameters) {
  validate(parameters_, axis);
}

void ControlAxis::reset(double position_m, double trim_m) {
  position_m_ = position_m;
  velocity_mps_ = 0.0;
  trim_m_ = trim_m;
  loader_force_n_ = mechanical_force_n_ = pilot_force_n_ = 0.0;
  backdrive_integral_n_ = backdrive_force_n_ = 0.0;
  on_mechanical_stop_ = false;
  stuck_ = true;
}

// Soft stop (progressive spring) and the unilateral hard-stop spring-damper, both loader forces.
double ControlAxis::stop_forces_n(double x, double v) const {
  const ControlAxisParameters& p = parameters_;
  double force = 0.0;
  const double soft_positive = p.soft_stop_fraction * p.positive_travel_m;
  const double soft_negative = -p.soft_stop_fraction * p.negative_travel_m;
  if (x > soft_positive) force -= p.soft_stop_stiffness_npm * (x - soft_positive);
  if (x < soft_negative) force -= p.soft_stop_stiffness_npm * (x - soft_negative);
  if (x > p.positive_travel_m) {
    const double penetration = x - p.positive_travel_m;
    force +=
        std::min(0.0, -(p.hard_stop_stiffness_npm * penetration + p.hard_stop_damping_nspm * v));
  }
  if (x < -p.negative_travel_m) {
    const double penetration = -p.negative_travel_m - x;
    force += std::max(0.0, p.hard_stop_stiffness_npm * penetration - p.hard_stop_damping_nspm * v);
  }
  return force;
}

// The centring spring with its breakout preload.
double ControlAxis::spring_force_n(double x, double trim_m, double gradient_npm) const {
  const ControlAxisParameters& p = parameters_;
  const double d = x - trim_m;
  return -gradient_npm * d - p.breakout_force_n * std::clamp(d / p.breakout_width_m, -1.0, 1.0);
}

double ControlAxis::static_feel_force_n(double x, double trim_m, double gradient_npm) const {
  return spring_force_n(x, trim_m, gradient_npm) + stop_forces_n(x, 0.0);
}

double ControlAxis::stiffest_spring_npm() const {
  const ControlAxisParameters& p = parameters_;
  const double wb = p.backdrive_natural_frequency_radps;
  return p.gradient_max_npm + p.breakout_force_n / p.breakout_width_m + p.soft_stop_stiffness_npm +
         p.hard_stop_stiffness_npm + p.mass_kg * wb * wb;
}

double ControlAxis::largest_damping_nspm() const {
  const ControlAxisParameters& p = parameters_;
  return p.viscous_damping_nspm + p.hard_stop_damping_nspm + p.safe_damping_nspm +
         2.0 * p.backdrive_damping_ratio * p.mass_kg * p.backdrive_natural_frequency_radps;
}

double ControlAxis::step_backdrive_integral(const AxisDrive& drive, double h) {
  const ControlAxisParameters& p = parameters_;
  if (!drive.backdrive_active || drive.force_gain < 1.0) {
    backdrive_integral_n_ = 0.0;
    return 0.0;
  }
  const double wb = p.backdrive_natural_frequency_radps;
  const double limit = 2.0 * p.coulomb_friction_n;
  backdrive_integral_n_ =
      std::clamp(backdrive_integral_n_ + h * p.mass_kg * wb * wb / kBackdriveIntegralTimeS *
                                             (drive.backdrive_target_m - position_m_),
                 -limit, limit);
  return backdrive_integral_n_;
}

// The autopilot's position servo: PD on the error, the integral, and the static feel force at
// the target fed forward (so that it holds the target against the spring exactly).
double ControlAxis::servo_force_n(const AxisDrive& drive) const {
  if (!drive.backdrive_active) return 0.0;
  const ControlAxisParameters& p = parameters_;
  const double wb = p.backdrive_natural_frequency_radps;
  const double hold = -static_feel_force_n(drive.backdrive_target_m, trim_m_, drive.gradient_npm);
  const double servo = p.mass_kg * wb * wb * (drive.backdrive_target_m - position_m_) -
                       2.0 * p.backdrive_damping_ratio * p.mass_kg * wb * velocity_mps_ +
                       backdrive_integral_n_ + hold;
  return std::clamp(servo, -p.backdrive_force_limit_n, p.backdrive_force_limit_n);
}

void ControlAxis::substep(const AxisDrive& drive, double h) {
  const ControlAxisParameters& p = parameters_;
  const double g = std::clamp(drive.force_gain, 0.0, 1.0);
  trim_m_ += std::clamp(drive.trim_target_m - trim_m_, -p.trim_rate_mps * h, p.trim_rate_mps * h);
  step_backdrive_integral(drive, h);
  const double servo = servo_force_n(drive);
  backdrive_force_n_ = g * servo;

  const double x = position_m_;
  const double v = velocity_mps_;
  const double feel = spring_force_n(x, trim_m_, drive.gradient_npm) + stop_forces_n(x, v) -
                      p.viscous_damping_nspm * v + servo + drive.shaker_force_n;
  const double safe = -p.safe_damping_nspm * v;
  const double without_friction = g * feel + (1.0 - g) * safe;
  const double other = drive.pilot_force_n + without_friction;

  // Karnopp dry friction (a loader force, faded with the rest of the feel).
  const double dry = g * p.coulomb_friction_n;
  const bool in_stick_band = std::abs(v) < p.stick_velocity_mps;
  double friction = 0.0;
  bool stuck = false;
  if (in_stick_band && std::abs(other) <= dry) {
    friction = -other;
    stuck = true;
  } else {
    friction = -dry * (in_stick_band ? sign(other) : sign(v));
  }
  const double loader =
      std::clamp(without_friction + friction, -p.motor_force_limit_n, p.motor_force_limit_n);
  const double net = drive.pilot_force_n + loader;
  double velocity = stuck && loader == without_friction + friction ? 0.0 : v + h * net / p.mass_kg;
  // Friction cannot reverse the motion: a step that would carry v through zero while the dry
  // friction could hold the other forces ends at rest.
  if (v != 0.0 && velocity * v < 0.0 && std::abs(other) <= dry) {
    velocity = 0.0;
    stuck = true;
  }
  double position = x + h * velocity;

  // The physical stop: an inelastic contact beyond the software hard stop.
  const double upper = p.positive_travel_m + p.mechanical_stop_beyond_m;
  const double lower = -p.negative_travel_m - p.mechanical_stop_beyond_m;
  on_mechanical_stop_ = position >= upper || position <= lower;
  mechanical_force_n_ = 0.0;
  if (on_mechanical_stop_) {
    position = std::clamp(position, lower, upper);
    const bool pressing = position == upper ? net > 0.0 : net < 0.0;
    if (pressing || velocity * (position == upper ? 1.0 : -1.0) > 0.0) velocity = 0.0;
    if (pressing) mechanical_force_n_ = -net;
  }
  position_m_ = position;
  velocity_mps_ = velocity;
  loader_force_n_ = loader;
  pilot_force_n_ = drive.pilot_force_n;
  stuck_ = stuck;
}

bool ControlAxis::in_soft_stop() const {
  return position_m_ > parameters_.soft_stop_fraction * parameters_.positive_travel_m ||
         position_m_ < -parameters_.soft_stop_fraction * parameters_.negative_travel_m;
}

bool ControlAxis::in_hard_stop() const {
  return position_m_ > parameters_.positive_travel_m ||
         position_m_ < -parameters_.negative_travel_m;
}

double ControlAxis::position_norm() const {
  const double travel =
      position_m_ >= 0.0 ? parameters_.positive_travel_m : parameters_.negative_travel_m;
  return std::clamp(position_m_ / travel, -1.0, 1.0);
}

double ControlAxis::velocity_norm_ps() const {
  const double travel =
      position_m_ >= 0.0 ? parameters_.positive_travel_m : parameters_.negative_travel_m;
  return velocity_mps_ / travel;
}

double ControlAxis::position_m_for_norm(double norm) const {
  const double clamped = std::clamp(norm, -1.0, 1.0);
  return clamped >= 0.0 ? clamped * parameters_.positive_travel_m
                        : clamped * parameters_.negative_travel_m;
}

}  // namespace fedsim::control_loading
