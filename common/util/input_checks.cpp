#include "common/util/input_checks.hpp"

#include <cmath>
#include <cstdio>
#include <stdexcept>

namespace fedsim::util {

void reject(std::string_view where, std::string_view field, const std::string& problem) {
  throw std::invalid_argument(std::string(where) + ": field '" + std::string(field) +
                              "': " + problem);
}

void require_in_range(double value, double lo, double hi, std::string_view where,
                      std::string_view field, const char* unit) {
  if (!std::isfinite(value)) reject(where, field, "not a finite number");
  if (value < lo || value > hi) {
    char text[160];
    std::snprintf(text, sizeof text, "%g %s is outside [%g, %g] %s", value, unit, lo, hi, unit);
    reject(where, field, text);
  }
}

void require_in_range(int value, int lo, int hi, std::string_view where, std::string_view field) {
  if (value < lo || value > hi) {
    reject(where, field,
           std::to_string(value) + " is outside [" + std::to_string(lo) + ", " +
               std::to_string(hi) + "]");
  }
}

}  // namespace fedsim::util
