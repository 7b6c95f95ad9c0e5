#include "flight/federate/pilot_input_gate.hpp"

#include <cmath>
#include <numeric>
#include <sstream>

namespace fedsim::flight {

const char* fault_kind(InputRejection why) {
  switch (why) {
    case InputRejection::kOtherAircraft: return "controls_other_aircraft";
    case InputRejection::kNotFinite: return "controls_not_finite";
    case InputRejection::kOutOfRange: return "controls_out_of_range";
    case InputRejection::kBadStamp: return "controls_bad_stamp";
  }
  return "controls_rejected";
}

namespace {

/// The first non-finite or out-of-range value of a sample's flown channels.
class ValueCheck {
 public:
  void operator()(const char* name, double value, double low, double high) {
    if (problem) return;
    std::ostringstream message;
    if (!std::isfinite(value)) {
      message << name << " = " << value << " is not finite";
      problem = InputProblem{InputRejection::kNotFinite, message.str()};
    } else if (value < low || value > high) {
      message << name << " = " << value << " is outside [" << low << ", " << high << "]";
      problem = InputProblem{InputRejection::kOutOfRange, message.str()};
    }
  }
  std::optional<InputProblem> problem;
};

std::optional<InputProblem> check_values(const msg::PilotControls& in) {
  ValueCheck check;
  check("elevator", in.elevator(), -1.0, 1.0);
  check("aileron", in.aileron(), -1.0, 1.0);
  check("rudder", in.rudder(), -1.0, 1.0);
  check("elevator_trim", in.elevator_trim(), -1.0, 1.0);
  check("aileron_trim", in.aileron_trim(), -1.0, 1.0);
  check("rudder_trim", in.rudder_trim(), -1.0, 1.0);
  for (std::size_t e = 0; e < in.throttle().size(); ++e) {
    check("throttle", in.throttle()[e], 0.0, 1.0);
    check("mixture", in.mixture()[e], 0.0, 1.0);
    check("propeller", in.propeller()[e], 0.0, 1.0);
  }
  check("flaps", in.flaps(), 0.0, 1.0);
  check("speedbrake", in.speedbrake(), 0.0, 1.0);
  check("brake_left", in.brake_left(), 0.0, 1.0);
  check("brake_right", in.brake_right(), 0.0, 1.0);
  check("nosewheel_steering", in.nosewheel_steering(), -1.0, 1.0);
  return check.problem;
}

}  // namespace

std::optional<InputProblem> check_pilot_input(const msg::PilotControls& in, std::uint64_t frame,
                                              const PilotInputLimits& limits) {
  if (in.aircraft_id() != limits.aircraft_id) {
    return InputProblem{InputRejection::kOtherAircraft,
                        "aircraft_id " + std::to_string(in.aircraft_id()) + " is not this aircraft (" +
                            std::to_string(limits.aircraft_id) + ")"};
  }
  const std::uint64_t stamp = in.stamp().frame();
  if (stamp > frame || frame - stamp > limits.max_stamp_age_frames) {
    return InputProblem{InputRejection::kBadStamp,
                        "stamped frame " + std::to_string(stamp) + ", read in frame " +
                            std::to_string(frame) + " (plausible: the " +
                            std::to_string(limits.max_stamp_age_frames) + " frames before it)"};
  }
  return check_values(in);
}

bool PilotInputScreen::accept(const msg::PilotControls& sample) {
  if (sample.aircraft_id() != limits_.aircraft_id) {
    last_other_id_.store(sample.aircraft_id());
    other_aircraft_.fetch_add(1);
    return false;
  }
  const std::int64_t newest = newest_frame_.load();
  const std::uint64_t stamp = sample.stamp().frame();
  if (newest >= 0 && stamp > static_cast<std::uint64_t>(newest) + limits_.max_stamp_age_frames) {
    last_future_stamp_.store(stamp);
    future_stamps_.fetch_add(1);
    return false;
  }
  return true;
}

PilotInputGate::PilotInputGate(PilotInputLimits limits) : limits_(limits) {}

std::optional<InputProblem> PilotInputGate::offer(const msg::PilotControls& sample, std::uint64_t frame) {
  auto problem = check_pilot_input(sample, frame, limits_);
  if (problem) {
    ++rejected_[static_cast<std::size_t>(problem->kind)];
    return problem;
  }
  last_good_ = sample;
  have_good_ = true;
  ++accepted_;
  return std::nullopt;
}

std::uint64_t PilotInputGate::rejected_total() const {
  return std::accumulate(rejected_.begin(), rejected_.end(), std::uint64_t{0});
}

PilotInputGate::WriterEvent PilotInputGate::writers_matched(int count) {
  if (count < 0) return WriterEvent::kNone;
  if (count > 1 && !several_writers_) {
    several_writers_ = true;
    ++second_writer_events_;
    return WriterEvent::kSecondWriter;
  }
  if (count <= 1 && several_writers_) {
    several_writers_ = false;
    return WriterEvent::kSingleWriterAgain;
  }
  return WriterEvent::kNone;
}

PilotInputGate::HoldEvent PilotInputGate::frame(std::uint64_t, bool new_sample) {
  if (new_sample) {
    quiet_frames_ = 0;
    if (!holding_) return HoldEvent::kNone;
    holding_ = false;
    return HoldEvent::kHoldEnded;
  }
  if (!have_good_) return HoldEvent::kNone;  // nothing to hold yet
  ++quiet_frames_;
  if (quiet_frames_ <= limits_.hold_after_frames) return HoldEvent::kNone;
  ++held_frames_;
  if (holding_) return HoldEvent::kNone;
  holding_ = true;
  return HoldEvent::kHoldStarted;
}

}  // namespace fedsim::flight
