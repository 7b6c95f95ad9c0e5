// One motion jack: a position servo, a second-order lag with velocity and acceleration limits,
// an end-stop cushion and the mechanical stroke (Allerton ch. 10.6-10.7 treat the hydraulics;
// here the closed servo loop is represented by its response, not by flows and pressures).
//
//   a_cmd = wa^2 (L_cmd - L) - 2 zeta wa v          (servo, bandwidth wa; the damping term
//                                                    trapezoidal in v, see jack_actuator.cpp)
//   a     = clamp(a_cmd, +-acceleration_limit)      (pump flow / force limit)
//   v'    = clamp(v + a h, +-velocity_limit)        (valve flow limit)
//   cushion: towards an end at distance d, |v'| <= sqrt(2 a_c (d - h |v'|))  (a_c: cushion
//            deceleration; the braking curve that stops the jack exactly at the end)
//   L'    = L + v' h, held in [min_length, max_length] (the mechanical stroke; v' = 0 there)
//
// integrated by semi-implicit (symplectic) Euler at the sub-step h (stable for wa h < 2 with the
// trapezoidal damping; the constructor requires wa h <= 0.2, where the discrete natural
// frequency is within 0.2% of wa and the damping within 0.1%). The cushion is the hydraulic
// deceleration of a jack at the end of its stroke: a jack running at full speed stops within
// v_max^2/(2 a_cushion) of the end, at a deceleration no larger than a_cushion, instead of hitting
// the stop. Input: the commanded length per sub-step [m]; output: length [m], rate [m/s].
#pragma once

namespace fedsim::motion {

struct JackActuatorParameters {
  double natural_frequency_radps = 50.0;    // wa: servo bandwidth, about 8 Hz [rad/s]
  double damping_ratio = 0.8;               // zeta [-]
  double velocity_limit_mps = 0.8;          // |v| limit [m/s]
  double acceleration_limit_mps2 = 10.0;    // |a| limit, about 1 g [m/s^2]
  double cushion_deceleration_mps2 = 10.0;  // braking in the end-stop cushion [m/s^2]
};

/// Every field positive and finite, damping in (0, 5] (std::invalid_argument naming the field).
void validate(const JackActuatorParameters& parameters);

class JackActuator {
 public:
  /// Stroke [min_length_m, max_length_m] (0 < min < max), sub-step h = substep_s (with
  /// natural_frequency_radps * substep_s <= 0.2), starting at rest at initial_length_m (inside).
  JackActuator(const JackActuatorParameters& parameters, double min_length_m, double max_length_m,
               double substep_s, double initial_length_m);

  /// One sub-step towards the commanded length (finite; std::invalid_argument otherwise).
  void step(double command_length_m);
  /// At rest at length_m (inside the stroke).
  void reset(double length_m);

  double length_m() const { return length_m_; }
  double velocity_mps() const { return velocity_mps_; }
  double acceleration_mps2() const { return acceleration_mps2_; }
  /// True when the last sub-step was velocity- or acceleration-limited.
  bool rate_limited() const { return rate_limited_; }
  /// True when the last sub-step braked in the cushion.
  bool cushioned() const { return cushioned_; }
  /// True when the jack sits on a mechanical end of its stroke.
  bool at_end_stop() const { return at_end_stop_; }

 private:
  double cushion_speed_limit_mps(double velocity_mps) const;

  JackActuatorParameters parameters_;
  double min_length_m_;
  double max_length_m_;
  double substep_s_;
  double length_m_;
  double velocity_mps_ = 0.0;
  double acceleration_mps2_ = 0.0;
  bool rate_limited_ = false;
  bool cushioned_ = false;
  bool at_end_stop_ = false;
};

}  // namespace fedsim::motion
