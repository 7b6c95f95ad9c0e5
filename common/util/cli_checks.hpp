// Command-line number checks that refuse NaN and infinities. CLI11's own Range, PositiveNumber
// and NonNegativeNumber compare with < and >, which a NaN passes: `--duration nan` ran forever.
// Every numeric option of fedsim uses these instead.
#pragma once

#include <CLI/CLI.hpp>

#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <limits>
#include <sstream>
#include <string>

namespace fedsim::util {

/// A finite number within [min, max] (the bounds included).
class FiniteRange : public CLI::Validator {
 public:
  FiniteRange(double min, double max) {
    std::ostringstream range;
    range << "[" << min << ", " << max << "]";
    name_ = "FINITE " + range.str();
    func_ = [min, max, text = range.str()](const std::string& input) -> std::string {
      errno = 0;
      char* end = nullptr;
      const double v = std::strtod(input.c_str(), &end);
      if (end == input.c_str() || *end != '\0' || errno == ERANGE || !std::isfinite(v)) {
        return "'" + input + "' is not a finite number";
      }
      if (v < min || v > max) return "'" + input + "' is outside " + text;
      return {};
    };
  }
};

/// A finite number >= 0 / > 0.
inline const FiniteRange kFiniteNonNegative{0.0, std::numeric_limits<double>::max()};
inline const FiniteRange kFinitePositive{std::numeric_limits<double>::denorm_min(),
                                         std::numeric_limits<double>::max()};

}  // namespace fedsim::util
