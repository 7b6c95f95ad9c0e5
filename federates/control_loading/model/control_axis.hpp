// One control-loading axis: the control (a mass at the grip) moved by the pilot's force and the
// loader's force, integrated over one inner-loop sub-step h.
//
//   m x'' = F_pilot + F_loader + F_mech
//   F_loader = clamp(g F_feel + (1 - g) F_safe, +-motor_force_limit)   g: force gain 0..1
//   F_feel   = -k(qbar) d - F_bo sat(d / w_bo) - c v + F_soft + F_hard + F_friction
//              + F_backdrive + F_shaker,    d = x - x_trim
//   F_soft   = -k_soft (|x| - f x_travel) sign(x) beyond the soft-stop start f x_travel
//   F_hard   = unilateral spring-damper beyond the travel: -(k_h p + c_h v), only pushing back
//   F_backdrive = clamp(m wb^2 (x_cmd - x) - 2 zeta_b m wb v + I + F_hold(x_cmd), +-F_bd_limit)
//              with F_hold the static feel force at x_cmd, and I' = (m wb^2 / T_i)(x_cmd - x)
//              (T_i = 0.15 s; |I| <= 2 F_c) the integral that works the dry friction off
//   F_safe   = -c_safe v (the safe state: no spring, no drive, only damping)
//   F_mech   = the physical stop mechanical_stop_beyond_m past the travel: an inelastic contact
//
// Breakout: a preloaded centring spring, the force -F_bo sign(d) built up over w_bo (0.5 mm)
// so that it is a continuous, integrable force; a pilot force below F_bo deflects the control
// by less than w_bo. Dry friction: Karnopp's model (D. Karnopp, "Computer simulation of
// stick-slip friction in mechanical dynamic systems", J. Dyn. Sys. Meas. Control 107(1),
// 1985): with |v| below the stick band and the other forces within +-F_c the control sticks
// (v = 0), otherwise -F_c sign(v) (or sign of the net force when starting).
//
// Integrator: semi-implicit (symplectic) Euler, v_{n+1} = v_n + h F(x_n, v_n)/m,
// x_{n+1} = x_n + h v_{n+1}. For a linear spring-damper (k, c) it is stable iff
// (w h)^2 + 2 c h/m < 4, w^2 = k/m (the Jury conditions of its 2x2 update matrix);
// ControlLoading picks h so that the stiffest combination (the hard stop, the breakout spring,
// the back-drive servo and every damper at once) gives (w h)^2 + 2 c h / m <= 2.
#pragma once

#include "control_loading/model/control_axis_parameters.hpp"

namespace fedsim::control_loading {

/// What acts on the axis during one sub-step (held across the sub-steps of a frame except the
/// pilot force of a simulated pilot, recomputed every sub-step).
struct AxisDrive {
  double pilot_force_n = 0.0;  // the pilot's force at the grip, + along + travel [N]
  double gradient_npm = 0.0;   // k(qbar) [N/m]
  double trim_target_m = 0.0;  // where the trim input puts the datum [m]
  bool backdrive_active = false;
  double backdrive_target_m = 0.0;  // commanded position [m]
  double shaker_force_n = 0.0;      // the shaker's force this sub-step [N]
  double force_gain = 1.0;          // g: 1 active, 0 safe, between while fading in [-]
};

class ControlAxis {
 public:
  /// Parameters validated (std::invalid_argument naming `axis`). At rest at x = 0, datum 0.
  ControlAxis(const ControlAxisParameters& parameters, const char* axis);

  /// One sub-step of h seconds.
  void substep(const AxisDrive& drive, double h);
  /// At rest at position_m with the datum at trim_m.
  void reset(double position_m, double trim_m);

  /// The static force the loader's feel applies at x with datum trim_m and gradient k (spring,
  /// breakout, soft and hard stops; no friction, no damping): - F_hold [N].
  double static_feel_force_n(double x_m, double trim_m, double gradient_npm) const;
  /// The stiffest (k [N/m], c [N s/m]) the axis can present, for choosing the sub-step.
  double stiffest_spring_npm() const;
  double largest_damping_nspm() const;

  double position_m() const { return position_m_; }
  double velocity_mps() const { return velocity_mps_; }
  double trim_m() const { return trim_m_; }
  /// The loader's force on the control in the last sub-step (+ along + travel) [N].
  double loader_force_n() const { return loader_force_n_; }
  /// The physical stop's force in the last sub-step [N] (0 off the stop).
  double mechanical_stop_force_n() const { return mechanical_force_n_; }
  double pilot_force_n() const { return pilot_force_n_; }
  /// The back-drive servo's force in the last sub-step (0 when inactive) [N].
  double backdrive_force_n() const { return backdrive_force_n_; }
  bool in_soft_stop() const;
  bool in_hard_stop() const;
  bool on_mechanical_stop() const { return on_mechanical_stop_; }
  bool stuck() const { return stuck_; }
  /// Position as a fraction of the travel on its side, clamped to [-1, 1] [-].
  double position_norm() const;
  /// Velocity per travel of the side it is on [1/s].
  double velocity_norm_ps() const;
  /// metres for a normalised position p in [-1, 1].
  double position_m_for_norm(double p) const;
  const ControlAxisParameters& parameters() const { return parameters_; }

 private:
  double stop_forces_n(double x_m, double v_mps) const;
  double spring_force_n(double x_m, double trim_m, double gradient_npm) const;
  double servo_force_n(const AxisDrive& drive) const;
  double step_backdrive_integral(const AxisDrive& drive, double h);

  ControlAxisParameters parameters_;
  double position_m_ = 0.0;
  double velocity_mps_ = 0.0;
  double trim_m_ = 0.0;
  double loader_force_n_ = 0.0;
  double mechanical_force_n_ = 0.0;
  double pilot_force_n_ = 0.0;
  double backdrive_integral_n_ = 0.0;
  double backdrive_force_n_ = 0.0;
  bool on_mechanical_stop_ = false;
  bool stuck_ = true;
};

}  // namespace fedsim::control_loading
