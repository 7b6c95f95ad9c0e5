#include "common/control/dead_band.hpp"

#include <sstream>
#include <stdexcept>

#include "common/control/parameter_checks.hpp"

namespace fedsim::control {
namespace {

constexpr const char* kBlock = "DeadBand";

double checked_half_width(double half_width) {
  require_non_negative(kBlock, "half_width", half_width);
  return half_width;
}

}  // namespace

DeadBand::DeadBand(double half_width)
    : DeadBand(-checked_half_width(half_width), checked_half_width(half_width)) {}

DeadBand::DeadBand(double lower, double upper) : lower_(lower), upper_(upper) {
  require_finite(kBlock, "lower", lower);
  require_finite(kBlock, "upper", upper);
  if (lower > upper) {
    std::ostringstream message;
    message.precision(9);
    message << kBlock << ": lower = " << lower << " must not exceed upper = " << upper;
    throw std::invalid_argument(message.str());
  }
}

double DeadBand::step(double u) {
  require_finite_input(kBlock, u);
  if (u > upper_) {
    output_ = u - upper_;
  } else if (u < lower_) {
    output_ = u - lower_;
  } else {
    output_ = 0.0;
  }
  return output_;
}

void DeadBand::reset(double y) {
  require_finite("DeadBand::reset", "output", y);
  output_ = y;
}

}  // namespace fedsim::control
