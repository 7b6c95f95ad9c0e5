#include "common/control/washout.hpp"

#include "common/control/first_order_discretisation.hpp"

namespace fedsim::control {
namespace {

constexpr const char* kBlock = "Washout";

}  // namespace

Washout::Washout(double time_constant_s, double dt_s, double gain)
    : LinearBlock<1>(kBlock, discretise_first_order(
                                 kBlock, {{"time_constant_s", time_constant_s}}, dt_s, gain,
                                 {{0.0, gain * time_constant_s}, {1.0, time_constant_s}},
                                 1.0 / time_constant_s)),
      time_constant_s_(time_constant_s),
      gain_(gain) {}

}  // namespace fedsim::control
