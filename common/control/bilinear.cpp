#include "common/control/bilinear.hpp"

#include <cmath>

#include "common/control/parameter_checks.hpp"

namespace fedsim::control {

double tustin_constant_per_s(double dt_s) {
  require_sample_period("bilinear", dt_s);
  return 2.0 / dt_s;
}

double prewarped_tustin_constant_per_s(double dt_s, double prewarp_radps) {
  require_sample_period("bilinear", dt_s);
  require_positive("bilinear", "prewarp_radps", prewarp_radps);
  require_below_nyquist("bilinear", "prewarp_radps", prewarp_radps, dt_s);
  return prewarp_radps / std::tan(0.5 * prewarp_radps * dt_s);
}

}  // namespace fedsim::control
