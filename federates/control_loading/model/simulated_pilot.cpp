#include "control_loading/model/simulated_pilot.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

namespace fedsim::control_loading {

void validate(const SimulatedPilotParameters& p) {
  auto positive = [](const char* field, double value) {
    if (!std::isfinite(value) || !(value > 0.0)) {
      throw std::invalid_argument(std::string("SimulatedPilotParameters: ") + field +
                                  " must be positive");
    }
  };
  positive("hand_stiffness_npm", p.hand_stiffness_npm);
  positive("hand_damping_nspm", p.hand_damping_nspm);
  positive("hand_force_limit_n", p.hand_force_limit_n);
}

double simulated_pilot_force_n(const SimulatedPilotParameters& p, double target_m,
                               double position_m, double velocity_mps,
                               double static_feel_at_target_n) {
  const double force = p.hand_stiffness_npm * (target_m - position_m) -
                       p.hand_damping_nspm * velocity_mps - static_feel_at_target_n;
  return std::clamp(force, -p.hand_force_limit_n, p.hand_force_limit_n);
}

}  // namespace fedsim::control_loading
