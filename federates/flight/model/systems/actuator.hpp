// Control-surface actuator: normalised command to surface deflection with lag, rate and
// position limits.
#pragma once

#include <limits>

namespace fedsim::flight {

/// One control-surface actuator (elevator, aileron, rudder, flap, trim tab...).
///
/// Input:  `command`, normalised (DESIGN.md control conventions): -1..1 for bidirectional
///         controls, 0..1 for one-sided ones (Params::command_min = 0). Out-of-range commands
///         are clamped.
/// Output: `position_rad`, the surface deflection in radians (sign as the pack states), and
///         its rate in rad/s.
///
/// Model, applied in this order each step:
///  1. demand = command * deflection_at_plus_one_rad            for command >= 0
///            = -command * deflection_at_minus_one_rad           for command <  0
///     (separate travel for +1 and -1, as JSBSim's aerosurface_scale);
///  2. first-order lag d(pos)/dt = (demand - pos) / time_constant_s, integrated exactly
///     (pos += (demand - pos)(1 - exp(-dt/tau))), so it is stable for any step size;
///  3. rate limit |d(pos)/dt| <= rate_limit_radps;
///  4. position limits [position_min_rad, position_max_rad].
/// No allocation; step() is O(1).
class Actuator {
 public:
  struct Params {
    /// Lowest accepted command: -1 (bidirectional) or 0 (one-sided, e.g. flaps).
    double command_min = -1.0;
    /// Deflection (rad) demanded by command +1.
    double deflection_at_plus_one_rad = 0.0;
    /// Deflection (rad) demanded by command -1 (usually of opposite sign). Unused if
    /// command_min = 0.
    double deflection_at_minus_one_rad = 0.0;
    /// First-order lag time constant (s); 0 = no lag. JSBSim's <lag> value L (1/s) is 1/L.
    double time_constant_s = 0.0;
    /// Largest surface rate (rad/s); +infinity = no rate limit.
    double rate_limit_radps = std::numeric_limits<double>::infinity();
    /// Mechanical stops (rad); +-infinity = none.
    double position_min_rad = -std::numeric_limits<double>::infinity();
    double position_max_rad = std::numeric_limits<double>::infinity();

    /// Throws std::invalid_argument naming the first bad field.
    void validate() const;
  };

  struct Inputs {
    double command = 0.0;  ///< normalised, see Params::command_min
  };

  struct Outputs {
    double position_rad = 0.0;  ///< surface deflection
    double rate_radps = 0.0;    ///< rate over the last step
    double demand_rad = 0.0;    ///< deflection the command asks for (before lag/limits)
  };

  explicit Actuator(Params params);

  /// Puts the surface at `position_rad` (clamped to the stops), at rest.
  void reset(double position_rad = 0.0);
  /// Advances the actuator by dt_s (> 0) seconds.
  void step(double dt_s, const Inputs& inputs);

  const Outputs& outputs() const { return outputs_; }
  const Params& params() const { return params_; }

  /// The deflection a command maps to (step 1 above), clamped command included.
  double demand_for(double command) const;

 private:
  double clamp_to_stops(double position_rad) const;

  Params params_;
  Outputs outputs_;
};

}  // namespace fedsim::flight
