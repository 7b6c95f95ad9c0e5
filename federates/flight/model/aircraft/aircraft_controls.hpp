// The pilot's commands to one aircraft as normalised numbers (DESIGN.md control conventions).
#pragma once

#include <array>
#include <cstddef>

namespace fedsim::flight {

/// What the pilot (or a script, or trim) asks of the aircraft. Ranges and signs as DESIGN.md:
/// elevator +1 = stick forward (nose down), aileron +1 = stick right (right wing down),
/// rudder +1 = right pedal (nose right). A trim channel is added to its primary control (seed
/// 3.7: "the trim input is added to the column position") and the sum is clamped to -1..1.
/// Commands outside their range are clamped and NaN reads as the neutral value, so a lost
/// input never reaches the model as NaN.
struct AircraftControls {
  static constexpr std::size_t kMaxEngines = 4;

  double elevator = 0.0;                                          ///< -1..1
  double aileron = 0.0;                                           ///< -1..1
  double rudder = 0.0;                                            ///< -1..1
  double elevator_trim = 0.0;                                     ///< -1..1, same sense as elevator
  double aileron_trim = 0.0;                                      ///< -1..1
  double rudder_trim = 0.0;                                       ///< -1..1
  std::array<double, kMaxEngines> throttle{0.0, 0.0, 0.0, 0.0};   ///< 0..1 per engine
  std::array<double, kMaxEngines> mixture{1.0, 1.0, 1.0, 1.0};    ///< 0..1, 1 = full rich
  std::array<double, kMaxEngines> propeller{1.0, 1.0, 1.0, 1.0};  ///< 0..1, 1 = fine / max rpm
  double flaps = 0.0;                                             ///< 0..1 of full flap travel
  double speedbrake = 0.0;                                        ///< 0..1
  double spoilers = 0.0;                                          ///< 0..1 (ground spoilers)
  bool gear_down = true;                                          ///< gear lever
  double brake_left = 0.0;                                        ///< 0..1
  double brake_right = 0.0;                                       ///< 0..1
  double steering = 0.0;                                          ///< -1..1, + = nose right

  /// Sets every engine's throttle.
  void set_throttle(double value) { throttle.fill(value); }

  /// Primary plus trim, clamped to -1..1 (what the actuator is commanded).
  double elevator_command() const;
  double aileron_command() const;
  double rudder_command() const;

  /// Every channel clamped into its range, NaN replaced by the neutral value (0, or 1 for
  /// mixture and propeller).
  AircraftControls clamped() const;

  friend bool operator==(const AircraftControls&, const AircraftControls&) = default;
};

}  // namespace fedsim::flight
