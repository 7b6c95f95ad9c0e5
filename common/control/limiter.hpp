// Position limiter (saturation): y = clamp(u, lower_limit, upper_limit). Authority limits,
// actuator travel stops. No state but the last output.
#pragma once

namespace fedsim::control {

class Limiter {
 public:
  /// Limits not NaN, lower_limit < upper_limit (+-infinity: no limit on that side).
  Limiter(double lower_limit, double upper_limit);

  /// clamp(u) for u finite.
  double step(double u);
  double output() const { return output_; }
  /// Sets the output held until the next step; y must lie within the limits (else
  /// std::invalid_argument).
  void reset(double y);
  /// True when the last step was limited.
  bool limited() const { return limited_; }

  double lower_limit() const { return lower_limit_; }
  double upper_limit() const { return upper_limit_; }

 private:
  double lower_limit_;
  double upper_limit_;
  double output_ = 0.0;
  bool limited_ = false;
};

}  // namespace fedsim::control
