// The stick shaker: the stall warning felt in the column. On when the angle of attack reaches
// alpha_on_rad, off again below alpha_on_rad - hysteresis_rad (so that it does not chatter on
// the threshold); while on, a force A sin(2 pi f t) on the axes whose shaker_force_n A > 0,
// t from the moment it came on. The threshold is the aircraft's: set it a margin below the
// pack's stall angle (e.g. the flight model's stall_hysteresis alpha_set_rad).
#pragma once

namespace fedsim::control_loading {

class StickShaker {
 public:
  /// alpha_on_rad finite, in (0, pi/2); hysteresis_rad >= 0 and below alpha_on_rad
  /// (std::invalid_argument otherwise).
  StickShaker(double alpha_on_rad, double hysteresis_rad);

  /// Moves the warning angle (the aircraft's at its present flap setting), keeping the
  /// hysteresis; false (nothing changes) unless alpha_on_rad lies in (hysteresis, pi/2).
  bool set_alpha_on(double alpha_on_rad);
  /// The warning state for this angle of attack (finite) [rad].
  bool update(double alpha_rad);
  /// Advances the time since the shaker came on by h seconds (nothing while off).
  void advance(double h_s);
  /// sin(2 pi f t) for an axis shaking at frequency_hz; 0 while off.
  double waveform(double frequency_hz) const;
  bool active() const { return active_; }
  /// Forces it off (the safe state).
  void reset();

 private:
  double alpha_on_rad_;
  double alpha_off_rad_;
  bool active_ = false;
  double time_on_s_ = 0.0;
};

}  // namespace fedsim::control_loading
