// A simulated pilot's hand, for running the loader without a force sensor (scripted profiles,
// batch runs, tests): it holds the grip like a spring-damper towards the position it wants and
// adds the force it knows the feel needs there (an ideal pilot who has learned the feel):
//   F_pilot = clamp(K_h (x_target - x) - C_h v - F_feel,static(x_target), +-hand_force_limit)
// Input: target position [m], the control's position [m] and velocity [m/s], the static feel
// force at the target [N]; output: the force on the grip [N], + along + travel.
#pragma once

namespace fedsim::control_loading {

struct SimulatedPilotParameters {
  double hand_stiffness_npm = 4000.0;  // K_h: the arm's stiffness [N/m]
  double hand_damping_nspm = 60.0;     // C_h [N s/m]
  double hand_force_limit_n = 400.0;   // the most the pilot pushes [N]
};

/// Every field positive and finite (std::invalid_argument naming it).
void validate(const SimulatedPilotParameters& parameters);

double simulated_pilot_force_n(const SimulatedPilotParameters& parameters, double target_m,
                               double position_m, double velocity_mps,
                               double static_feel_at_target_n);

}  // namespace fedsim::control_loading
