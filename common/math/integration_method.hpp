// Names of the numerical integration methods (seed 2.5) selectable at run time.
#pragma once

#include <string>
#include <string_view>

namespace fedsim {

enum class IntegrationMethod {
  kEuler,  // forward Euler, first order (eq. 2.52)
  kRk4,    // classical fourth-order Runge-Kutta
  kAb2,    // Adams-Bashforth, second order
  kAb3,    // Adams-Bashforth, third order
  kAb4,    // Adams-Bashforth, fourth order
};

/// "euler", "rk4", "ab2", "ab3", "ab4" (case-insensitive); throws std::invalid_argument.
IntegrationMethod integration_method_from_name(std::string_view name);
std::string_view to_string(IntegrationMethod method);
/// Formal order of accuracy (global error ~ h^order).
int order_of(IntegrationMethod method);

}  // namespace fedsim
