// Gain: y = K u. No state; the gain may be changed between steps (gain scheduling).
#pragma once

namespace fedsim::control {

class Gain {
 public:
  /// gain: K [output unit per input unit], finite (zero allowed).
  explicit Gain(double gain);

  /// y = K u; u must be finite.
  double step(double u);
  double output() const { return output_; }
  /// Sets the output held until the next step (a stateless block has no other state).
  void reset(double output);

  double gain() const { return gain_; }
  /// A new K (finite) from the next step on.
  void set_gain(double gain);

 private:
  double gain_;
  double output_ = 0.0;
};

}  // namespace fedsim::control
