// Checks for every number that enters the visual model from outside (configuration, the eye
// pose, the environment, runway records): a NaN, an infinity or a value out of its range throws
// std::invalid_argument "<where>: field '<field>': <problem>".
#pragma once

#include <string>

namespace fedsim::visual {

/// Throws unless lo <= value <= hi and value is finite; `unit` is shown with the numbers.
void require_in_range(double value, double lo, double hi, const std::string& where,
                      const std::string& field, const char* unit);
void require_in_range(int value, int lo, int hi, const std::string& where,
                      const std::string& field);
[[noreturn]] void reject(const std::string& where, const std::string& field,
                         const std::string& problem);

}  // namespace fedsim::visual
