// One batch run: the model flown frame by frame from its start state, controls from a scripted
// profile (or held), every frame recorded.
#pragma once

#include <functional>
#include <optional>

#include "flight/fly/csv_recorder.hpp"
#include "flight/model/aircraft/aircraft_model.hpp"
#include "io/model/input_profile.hpp"

namespace fedsim::flight {

class BatchFlight {
 public:
  /// Called now and then with the simulated time and the total.
  using Progress = std::function<void(double simulated_s, double total_s)>;

  /// `start_controls` are the controls the run starts with (trimmed, or the IC file's). With a
  /// profile they are replaced (absolute) or offset (relative) by its channels.
  BatchFlight(AircraftModel& model, const AircraftControls& start_controls,
              std::optional<io::InputProfile> profile, bool profile_relative);

  /// Flies round(duration * rate) frames of 1/rate seconds, writing the start and every
  /// `output_every`th frame (and the last) to `recorder`.
  void run(double duration_s, double rate_hz, int output_every, CsvRecorder& recorder,
           const Progress& progress);

 private:
  AircraftControls controls_at(double t_s);

  AircraftModel& model_;
  AircraftControls start_controls_;
  io::ControlInputs start_channels_;
  io::ControlInputs channels_;
  std::optional<io::InputProfile> profile_;
  bool relative_;
};

}  // namespace fedsim::flight
