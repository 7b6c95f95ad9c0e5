// Wing leveller: the light aircraft's single-axis autopilot that holds the wings level, the
// JSBSim C172 autopilot's "Roll wing leveler" (aircraft/c172x/c172ap.xml), carried by the pack
// as flight_controls.wing_leveller (data/aircraft/README.md) and engaged by the pilot's switch.
//
// Input:  bank angle phi [rad] (+ right wing down) and its Euler rate dphi/dt [rad/s], the
//         pilot's aileron command with trim (normalised -1..1), engaged flag, weight on wheels.
// Output: aileron command [normalised, + = right wing down] that the executive adds to the
//         pilot's aileron and trim before the aileron actuator (JSBSim's "fcs/roll-trim-sum",
//         clipped to -1..1 there).
// Model:  JSBSim's PID on the bank with the switch's sign,
//           command = -(Kp phi + Ki integral(phi dt) + Kd dphi/dt),
//         the integral by the rectangular rule (I += Ki phi dt). Departures from JSBSim, all
//         said in the pack's notes: its integral is 2nd-order Adams-Bashforth (its default)
//         and its rate the difference of phi between frames (both the same in the limit of
//         small steps; the rate here is the Euler rate from the body rates), and the integral
//         stops while the summed command is saturated and phi would push it further
//         (conditional integration, Astrom & Hagglund 2006, 3.5): JSBSim's PID has no
//         anti-windup there, so after a recovery from a steep bank at full aileron its integral
//         would carry the aircraft past level. Disengaged (JSBSim's trigger -1) the integral
//         is reset and the output is 0; with airborne_only the output is 0 and the integral
//         reset while a wheel carries load (JSBSim's selector tests gear WOW == 0).
// No allocation; step() is O(1).
#pragma once

namespace fedsim::flight {

class WingLeveller {
 public:
  struct Params {
    double bank_gain_per_rad = 0.0;             ///< Kp: aileron command per rad of bank
    double bank_integral_gain_per_rad_s = 0.0;  ///< Ki: per rad s of integrated bank
    double bank_rate_gain_per_radps = 0.0;      ///< Kd: per rad/s of bank rate
    bool airborne_only = true;                  ///< no command with weight on wheels
    /// Throws std::invalid_argument naming the first bad field.
    void validate() const;
  };
  struct Inputs {
    double bank_rad = 0.0;
    double bank_rate_radps = 0.0;
    double pilot_aileron_command = 0.0;  ///< pilot + trim, the sum the command joins
    bool engaged = false;
    bool weight_on_wheels = false;
  };
  struct Outputs {
    double aileron_command = 0.0;  ///< within [-1 - pilot, 1 - pilot]: what acts after the clip
    double integral = 0.0;         ///< Ki integral(phi dt), the I term
    bool active = false;           ///< engaged and allowed to act (airborne when airborne_only)
  };

  explicit WingLeveller(Params params);
  /// At rest: no command, integral zero.
  void reset();
  /// One step of dt_s >= 0 (0: the command for the present inputs, the integral unchanged).
  /// A non-finite input disengages it for the step (output 0, integral reset).
  void step(double dt_s, const Inputs& inputs);
  const Outputs& outputs() const { return outputs_; }
  const Params& params() const { return params_; }

  /// The Euler bank rate from body rates p, q, r and the attitude (the seed's eq 3.48:
  /// dphi/dt = p + (q sin phi + r cos phi) tan theta); p alone where cos theta is
  /// near zero (the vertical attitude, where the Euler rates are undefined).
  static double bank_rate_radps(double p_radps, double q_radps, double r_radps, double bank_rad,
                                double pitch_rad);

 private:
  Params params_;
  Outputs outputs_;
};

}  // namespace fedsim::flight
