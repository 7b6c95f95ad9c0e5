// One batch run of the flight model.
#include "flight/fly/batch_flight.hpp"

#include <chrono>
#include <cmath>

#include "flight/fly/control_mapping.hpp"

namespace fedsim::flight {

namespace {
constexpr double kProgressIntervalS = 2.0;  // wall-clock seconds between progress reports
}

BatchFlight::BatchFlight(AircraftModel& model, const AircraftControls& start_controls,
                         std::optional<io::InputProfile> profile, bool profile_relative)
    : model_(model),
      start_controls_(start_controls),
      start_channels_(to_control_inputs(start_controls)),
      channels_(start_channels_),
      profile_(std::move(profile)),
      relative_(profile_relative) {}

AircraftControls BatchFlight::controls_at(double t_s) {
  if (!profile_) return start_controls_;
  if (relative_) {
    profile_->sample_relative(t_s, start_channels_, channels_);
  } else {
    profile_->sample(t_s, channels_);
  }
  return from_control_inputs(channels_, start_controls_);
}

void BatchFlight::run(double duration_s, double rate_hz, int output_every, CsvRecorder& recorder,
                      const Progress& progress) {
  using Clock = std::chrono::steady_clock;
  const double dt_s = 1.0 / rate_hz;
  const long frames = std::lround(duration_s * rate_hz);
  auto last_report = Clock::now();
  for (long frame = 0;; ++frame) {
    // Row k: the state at t_k and the commands that act from t_k to t_k+1.
    const double t_s = static_cast<double>(frame) * dt_s;
    model_.set_controls(controls_at(t_s));
    if (frame % output_every == 0 || frame == frames) {
      recorder.write(model_.outputs(), model_.controls());
    }
    if (frame == frames) break;
    model_.step(dt_s);
    if (progress &&
        Clock::now() - last_report > std::chrono::duration<double>(kProgressIntervalS)) {
      last_report = Clock::now();
      progress(t_s + dt_s, duration_s);
    }
  }
}

}  // namespace fedsim::flight
