// One term of an aerodynamic coefficient build-up: a constant or table times named variables.
#pragma once

#include <cstddef>
#include <span>
#include <string>
#include <vector>

#include "flight/model/aircraft/aero_lookup.hpp"

namespace fedsim::flight {

/// A coefficient contribution such as Cm_q * q_hat or CL(alpha, flap): the lookup's value
/// multiplied by the values of the `multiplier_slots`. The same shape serves for the pack's
/// named factors (e.g. a ground-effect multiplier), whose value then fills a slot of its own.
struct AeroTerm {
  std::string name;
  std::string description;
  AeroLookup lookup;
  std::vector<std::size_t> multiplier_slots;  // resolved at load time

  double evaluate(std::span<const double> slots) const {
    double value = lookup(slots);
    for (const std::size_t slot : multiplier_slots) value *= slots[slot];
    return value;
  }
};

}  // namespace fedsim::flight
