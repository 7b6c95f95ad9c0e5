// Propeller blade-angle control: fixed pitch, or a constant-speed unit with feathering.
#pragma once

namespace fedsim::flight {

/// Blade angle of a fixed-pitch or a constant-speed (governed) propeller (seed 3.8.1).
///
/// Inputs:  propeller lever (0..1, 1 = fine pitch / high rpm), feather command, engine rpm.
/// Outputs: blade angle (rad), the rpm the governor is set to.
///
/// Fixed pitch: the blade stays at fine_pitch_rad.
/// Constant speed: the lever selects rpm by the square law of eq. 3.113,
///   N_sel = max(governor_min_rpm, governor_max_rpm * pl^2),
/// and the flyweight governor moves the blades at a rate proportional to the overspeed,
///   d(beta)/dt = gain * (N - N_sel), limited to +-pitch_rate_limit_radps,
/// within [fine_pitch_rad, coarse_pitch_rad]: overspeed coarsens the blades, loading the
/// engine, underspeed fines them. Feather drives the blades to feather_pitch_rad at the rate
/// limit (book: about 90 deg, minimal drag); unfeathering returns them at the same rate.
/// If the engine cannot reach N_sel the blades rest on the fine stop, as the book describes.
class PropellerGovernor {
 public:
  struct Params {
    bool constant_speed = false;
    double fine_pitch_rad = 0.0;        ///< fixed-pitch blade angle, or the fine stop
    double coarse_pitch_rad = 0.0;      ///< coarse stop of the governed range
    double feather_pitch_rad = 0.0;     ///< feathered angle (>= coarse)
    double governor_max_rpm = 2700.0;   ///< engine rpm selected by lever 1 (eq. 3.113: 2700)
    double governor_min_rpm = 0.0;      ///< lowest rpm the governor selects
    double gain_radps_per_rpm = 0.002;  ///< blade rate per rpm of overspeed
    double pitch_rate_limit_radps = 0.35;

    void validate() const;
  };

  struct Inputs {
    double lever = 1.0;  ///< 0..1 (clamped)
    bool feather = false;
    double engine_rpm = 0.0;
  };

  struct Outputs {
    double blade_angle_rad = 0.0;
    double selected_rpm = 0.0;
  };

  explicit PropellerGovernor(Params params);

  /// Blades to the fine stop (or the fixed angle).
  void reset();
  void reset(double blade_angle_rad);
  void step(double dt_s, const Inputs& in);

  const Outputs& outputs() const { return outputs_; }
  const Params& params() const { return params_; }
  double selected_rpm(double lever) const;

 private:
  double blade_rate_radps(const Inputs& in) const;

  Params params_;
  Outputs outputs_;
};

}  // namespace fedsim::flight
