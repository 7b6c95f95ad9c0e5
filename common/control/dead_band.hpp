// Dead-band: no output while the input lies within [lower, upper], and outside it the input less
// the band edge, so the output is continuous (no jump at the edge):
//   y = u - upper (u > upper),  0 (lower <= u <= upper),  u - lower (u < lower).
// Stick and pedal centring, hysteresis-free thresholds. No state but the last output.
#pragma once

namespace fedsim::control {

class DeadBand {
 public:
  /// The symmetric band [-half_width, +half_width]: half_width >= 0, finite.
  explicit DeadBand(double half_width);
  /// The band [lower, upper]: finite, lower <= upper.
  DeadBand(double lower, double upper);

  double step(double u);
  double output() const { return output_; }
  /// Sets the output held until the next step.
  void reset(double y);

  double lower() const { return lower_; }
  double upper() const { return upper_; }

 private:
  double lower_;
  double upper_;
  double output_ = 0.0;
};

}  // namespace fedsim::control
