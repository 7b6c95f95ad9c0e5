#include "common/control/washout.hpp"

namespace fedsim::control {

Washout::Washout(double time_constant_s, double dt_s, double gain)
    : FirstOrderBlock("Washout", time_constant_s, dt_s, gain, {0.0, gain * time_constant_s}) {}

}  // namespace fedsim::control
