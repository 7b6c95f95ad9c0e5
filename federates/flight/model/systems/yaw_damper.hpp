// Yaw damper: a rudder command from the body yaw rate relative to the air mass, the stability
// augmentation of a jet transport's Dutch roll (seed ch. 4; the JSBSim 737's <flight_control>
// "Yaw Damper" / "Yaw Damper Final" chain, which this reproduces from the pack).
//
// Input:  yaw rate r relative to the air mass [rad/s] (body z), Mach number, engaged flag.
// Output: rudder command [normalised, + = nose right] that the executive adds to the pilot's
//         rudder and rudder trim before the rudder actuator (JSBSim's "Rudder Sum", clipped to
//         -1..1 there).
// Model:  command = clamp(K(M) x W(r), -authority, authority), K(M) the pack's gain table
//         (negative: a yaw rate to the right gives left rudder), W a first-order washout
//         tau s / (tau s + 1) when washout_time_constant_s > 0 (then a steady turn needs no
//         damper rudder), else W = 1 (the JSBSim 737's pure gain). The washout is integrated
//         exactly for the step taken: its low-pass state l follows r as
//         l += (r - l)(1 - exp(-dt / tau)), W(r) = r - l. Disengaged: output 0 and the washout
//         rests on the present rate, so engagement does not kick the rudder.
// No allocation; step() is O(log n) (the table lookup).
#pragma once

#include "common/math/interpolation.hpp"

namespace fedsim::flight {

class YawDamper {
 public:
  struct Params {
    Table1D gain_per_radps;               ///< K(Mach): rudder command per rad/s of yaw rate
    double washout_time_constant_s = 0.0; ///< 0: no washout
    double authority = 1.0;               ///< |command| limit, (0, 1]
    /// Throws std::invalid_argument naming the first bad field.
    void validate() const;
  };
  struct Inputs {
    double yaw_rate_radps = 0.0;  ///< body r relative to the air mass
    double mach = 0.0;
    bool engaged = true;
  };
  struct Outputs {
    double rudder_command = 0.0;  ///< normalised, + nose right
  };

  explicit YawDamper(Params params);
  /// At rest on the yaw rate `yaw_rate_radps`: the output is the steady one for it (K r with
  /// no washout, 0 with one).
  void reset(double yaw_rate_radps, double mach, bool engaged);
  void step(double dt_s, const Inputs& inputs);
  const Outputs& outputs() const { return outputs_; }
  const Params& params() const { return params_; }

 private:
  double command(double washed_rate_radps, double mach) const;
  Params params_;
  Outputs outputs_;
  double low_pass_radps_ = 0.0;  // the washout's low-passed rate
};

}  // namespace fedsim::flight
