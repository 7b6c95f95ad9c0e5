// Field checks for the systems models' Params::validate(): each throws std::invalid_argument
// with the field's name, so that a pack loader can point at the offending entry.
#pragma once

#include <Eigen/Core>
#include <cmath>
#include <stdexcept>
#include <string>

#include "common/math/interpolation.hpp"

namespace fedsim::flight::param_checks {

[[noreturn]] inline void fail(const std::string& field, const std::string& rule, double value) {
  throw std::invalid_argument(field + " " + rule + " (got " + std::to_string(value) + ")");
}

inline void finite(double value, const std::string& field) {
  if (!std::isfinite(value)) fail(field, "must be finite", value);
}

inline void positive(double value, const std::string& field) {
  if (!(value > 0.0) || !std::isfinite(value)) fail(field, "must be positive and finite", value);
}

inline void non_negative(double value, const std::string& field) {
  if (!(value >= 0.0) || !std::isfinite(value)) fail(field, "must be >= 0 and finite", value);
}

/// lo <= value <= hi (and not NaN).
inline void in_range(double value, double lo, double hi, const std::string& field) {
  if (!(value >= lo && value <= hi)) {
    fail(field, "must lie in [" + std::to_string(lo) + ", " + std::to_string(hi) + "]", value);
  }
}

inline void finite(const Eigen::Vector3d& v, const std::string& field) {
  for (int i = 0; i < 3; ++i) finite(v[i], field + "[" + std::to_string(i) + "]");
}

inline void not_empty(const Table1D& table, const std::string& field) {
  if (table.empty()) throw std::invalid_argument(field + " must not be empty");
}

inline void not_empty(const Table2D& table, const std::string& field) {
  if (table.empty()) throw std::invalid_argument(field + " must not be empty");
}

}  // namespace fedsim::flight::param_checks
