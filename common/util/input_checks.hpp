// Checks for every number that enters the visual model from outside (configuration, the eye
// pose, the environment, runway records): a NaN, an infinity or a value out of its range throws
// std::invalid_argument "<where>: field '<field>': <problem>".
#pragma once

#include <string>
#include <string_view>

namespace fedsim::util {

/// Throws unless lo <= value <= hi and value is finite; `unit` is shown with the numbers.
/// Allocation-free unless it throws (the checks run every frame).
void require_in_range(double value, double lo, double hi, std::string_view where,
                      std::string_view field, const char* unit);
void require_in_range(int value, int lo, int hi, std::string_view where, std::string_view field);
[[noreturn]] void reject(std::string_view where, std::string_view field,
                         const std::string& problem);

}  // namespace fedsim::util
