// Names of the numerical integration methods.
#include "common/math/integration_method.hpp"

#include <algorithm>
#include <cctype>
#include <stdexcept>

namespace fedsim {

namespace {
constexpr IntegrationMethod kAll[] = {IntegrationMethod::kEuler, IntegrationMethod::kRk4,
                                      IntegrationMethod::kAb2, IntegrationMethod::kAb3,
                                      IntegrationMethod::kAb4};
}  // namespace

std::string_view to_string(IntegrationMethod method) {
  switch (method) {
    case IntegrationMethod::kEuler: return "euler";
    case IntegrationMethod::kRk4: return "rk4";
    case IntegrationMethod::kAb2: return "ab2";
    case IntegrationMethod::kAb3: return "ab3";
    case IntegrationMethod::kAb4: return "ab4";
  }
  return "unknown";
}

IntegrationMethod integration_method_from_name(std::string_view name) {
  std::string lower(name);
  std::transform(lower.begin(), lower.end(), lower.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  for (IntegrationMethod method : kAll) {
    if (lower == to_string(method)) return method;
  }
  throw std::invalid_argument("unknown integration method '" + std::string(name) +
                              "' (expected euler, rk4, ab2, ab3 or ab4)");
}

int order_of(IntegrationMethod method) {
  switch (method) {
    case IntegrationMethod::kEuler: return 1;
    case IntegrationMethod::kRk4: return 4;
    case IntegrationMethod::kAb2: return 2;
    case IntegrationMethod::kAb3: return 3;
    case IntegrationMethod::kAb4: return 4;
  }
  return 0;
}

}  // namespace fedsim
