// Parameters of one control-loading axis (pitch: column/stick fore-aft; roll: wheel/stick
// lateral, as travel at the grip; yaw: pedals). Positions are travel at the grip [m], + in the
// + sense of the normalised control (docs/frames.md: elevator + stick forward, aileron + stick
// right, rudder + right pedal); forces at the grip [N], + along + travel.
//
// Defaults: representative of a mid-size transport's primary controls, chosen for fedsim (not a
// manufacturer's data; replace them from the aircraft's control-force data, e.g. the static
// force-deflection plots of its qualification test guide). The gradient is proportional to
// dynamic pressure (the hinge moment of an unboosted surface, seed 1.4.10: "the force per unit
// displacement increases with airspeed"), held between a floor (the feel at rest: centring
// springs) and a ceiling (the loader's authority).
#pragma once

#include <string_view>

namespace fedsim::control_loading {

struct ControlAxisParameters {
  // The control.
  double mass_kg = 3.0;             // effective mass at the grip [kg]
  double positive_travel_m = 0.10;  // software hard stop at +travel (forward/right) [m]
  double negative_travel_m = 0.15;  // ... at -travel (aft/left), a magnitude [m]
  // Feel.
  double breakout_force_n = 10.0;      // force to move the control off its trim datum [N]
  double breakout_width_m = 0.0005;    // travel over which the breakout force builds up [m]
  double coulomb_friction_n = 4.0;     // dry friction, opposing motion [N]
  double viscous_damping_nspm = 20.0;  // viscous friction [N s/m]
  double gradient_per_qbar_m = 0.35;   // force gradient per dynamic pressure [(N/m)/Pa = m]
  double gradient_min_npm = 150.0;     // floor of the gradient (at rest) [N/m]
  double gradient_max_npm = 4000.0;    // ceiling of the gradient [N/m]
  // Trim.
  double trim_travel_m = 0.05;  // datum offset at trim input +-1 [m]
  double trim_rate_mps = 0.01;  // speed of the trim datum (trim motor) [m/s]
  // End stops.
  double soft_stop_fraction = 0.9;            // the soft stop starts at this fraction of travel [-]
  double soft_stop_stiffness_npm = 10000.0;   // added stiffness in the soft-stop zone [N/m]
  double hard_stop_stiffness_npm = 200000.0;  // software hard stop beyond the travel [N/m]
  double hard_stop_damping_nspm = 1000.0;     // damping while in the hard stop [N s/m]
  double mechanical_stop_beyond_m = 0.005;    // the physical stop this far past the travel [m]
  // Stick shaker (pitch only by default; 0 disables it on an axis).
  double shaker_force_n = 0.0;        // force amplitude [N]
  double shaker_frequency_hz = 15.0;  // [Hz]
  // Back-drive (autopilot): a position servo with a force limit.
  double backdrive_natural_frequency_radps = 15.0;  // [rad/s]
  double backdrive_damping_ratio = 0.9;             // [-]
  double backdrive_force_limit_n = 150.0;           // |servo force| limit [N]
  // Safety.
  double motor_force_limit_n = 600.0;  // |loader force| never exceeds this [N]
  double velocity_trip_mps = 2.0;      // |velocity| beyond this trips the safe state [m/s]
  double safe_damping_nspm = 40.0;     // damping applied in the safe state [N s/m]
  double stick_velocity_mps = 1e-3;    // Karnopp stick band: below it dry friction can hold [m/s]
};

/// Representative pitch (column), roll (wheel) and yaw (pedal) axes.
ControlAxisParameters default_pitch_axis();
ControlAxisParameters default_roll_axis();
ControlAxisParameters default_yaw_axis();

/// Checks every field (finite, positive where it must be, gradient_min <= gradient_max, soft
/// fraction in (0, 1), trim travel within the travel, back-drive and breakout forces below the
/// motor limit); throws std::invalid_argument "ControlAxisParameters[<axis>]: <field> = <v> ...".
void validate(const ControlAxisParameters& parameters, std::string_view axis);

/// The force gradient at dynamic pressure qbar_pa (>= 0): clamp(gradient_per_qbar_m qbar,
/// gradient_min, gradient_max) [N/m].
double scheduled_gradient_npm(const ControlAxisParameters& parameters, double qbar_pa);

}  // namespace fedsim::control_loading
