// Rate limiter: the output follows the input but moves at most rise_rate_per_s upwards and
// fall_rate_per_s downwards (per second, in the input's unit): y_n = y_{n-1} +
// clamp(u_n - y_{n-1}, -fall dt, +rise dt). Actuator rate limits, command smoothing.
// Sampled every dt_s; starts at output 0 unless reset.
#pragma once

namespace fedsim::control {

class RateLimiter {
 public:
  /// The same limit both ways: rate_limit_per_s > 0, finite; dt_s > 0.
  RateLimiter(double rate_limit_per_s, double dt_s);
  /// rise_rate_per_s, fall_rate_per_s (magnitudes) > 0, finite; dt_s > 0.
  RateLimiter(double rise_rate_per_s, double fall_rate_per_s, double dt_s);

  /// The output after one step towards u (finite).
  double step(double u);
  double output() const { return output_; }
  /// Output y from now on (a held input y gives no motion).
  void reset(double y);
  /// True when the last step was limited.
  bool limited() const { return limited_; }

  double rise_rate_per_s() const { return rise_rate_per_s_; }
  double fall_rate_per_s() const { return fall_rate_per_s_; }

 private:
  double rise_rate_per_s_;
  double fall_rate_per_s_;
  double max_rise_per_step_;
  double max_fall_per_step_;
  double output_ = 0.0;
  bool limited_ = false;
};

}  // namespace fedsim::control
