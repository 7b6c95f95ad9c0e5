#include "common/control/first_order_lag.hpp"

namespace fedsim::control {

FirstOrderLag::FirstOrderLag(double time_constant_s, double dt_s, double gain)
    : FirstOrderBlock("FirstOrderLag", time_constant_s, dt_s, gain, {gain, 0.0}) {}

}  // namespace fedsim::control
