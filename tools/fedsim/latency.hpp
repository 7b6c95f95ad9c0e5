// `fedsim latency`: the transport delay of the federation (14 CFR Part 60 Appendix A: from a
// control input to the visual, motion and instrument responses, 150 ms for aeroplanes C/D; seed
// section 7.3 "Latency"), measured end to end, as docs/latency.md describes.
//
// It starts a small federation through `fedsim run` (timing, io flying a generated profile of
// doublets about the trim on the axis's control: elevator, aileron or rudder; the first edge of
// each is the step; flight, visual at the full frame rate with a small picture aimed at the
// horizon (at the ground for yaw), motion, displays drawing the PFD), watches it from its own
// participant, and for every step and every path finds the first output that shows the step:
//   controls        fedsim/pilot_controls: the input itself (frame S, the step's frame)
//   flight_state    fedsim/aircraft_state: pitch (roll, heading) attitude and rate leave their trend
//   visual_image    fedsim/visual_picture (channel 0): the horizon moves (pitch), tilts (roll), or
//                   the ground shifts sideways (yaw) in the decoded picture
//   motion_platform fedsim/motion_state: a jack leaves its trend
//   pfd_image       fedsim/visual_picture (channel 100): the PFD's horizon moves (pitch), tilts
//                   (roll), or its heading scale turns (yaw)
// --loader puts fedsim-control-loading in the path (Part 60 measures through the interface): the
// step becomes a force doublet on the axis's force sensor (fedsim-io --loader-in-the-loop), and
//   loader          fedsim/control_loading_state: the loader's position of the axis's control
// is a path of its own; an output found to move before its cause could reach it is named.
// A path's delay is counted in frames (the frame the output was produced in minus S) and, in
// realtime, in milliseconds from the timing federate's publish of tick S (the instant the input
// was sampled) to the output's arrival (for a picture: its visual_status, sent when the image is
// complete, before the JPEG). Pictures carry the aircraft-state frame they show (their stamp);
// the frame they were drawn in is that frame + 1 in lockstep (frame N reads N-1) and, in
// realtime, the frame of the last tick seen before their status arrived.
//
// The last stdout line is one JSON object; DIR/latency.md holds the same tables. Exit status: 0
// every path responded to every step; 1 a path gave no response (named) or the run failed; 2
// bad options.
#pragma once

#include "common/runtime/dds_participant.hpp"

#include <nlohmann/json.hpp>

#include <cstdint>
#include <iosfwd>
#include <map>
#include <string>
#include <vector>

namespace CLI {
class App;
}

namespace fedsim::launcher {

struct LatencyOptions {
  std::string mode = "lockstep";  // lockstep | realtime
  std::string axis = "pitch";     // pitch | roll | yaw: the control stepped (elevator, aileron, rudder) and what is watched
  double rate_hz = 50.0;         // 10..60: every frame's picture is streamed (fedsim-visual: at most 60 a second)
  int steps = 5;                  // doublets measured; the first edge of each is the step
  double amplitude = 0.7;         // the control's step, normalised, added to the trim (+ nose down, right wing down,
                                  // nose right); 0: none. The command line's default is the axis's (default_amplitude)
  bool loader = false;            // --loader: fedsim-control-loading in the path; the step is a force doublet
  double force_n = 150.0;         // --loader: the force step on the axis's control [N]; 0: none
  double pulse_s = 0.04;          // each half of the doublet [s]
  double first_step_s = 9.0;      // sim time of the first step (the platform engages in ~5.2 s, then settles) [s]
  double interval_s = 3.0;        // between steps [s]
  double timeout_s = 0.0;         // the whole run at most [s]; 0: 60 s + the simulated time
  std::string out_dir = "out/latency";
  runtime::ParticipantOptions dds;
};

/// The step `fedsim latency --axis AXIS` takes when --amplitude is not given (docs/latency.md).
double default_amplitude(const std::string& axis);
/// The profile column the axis steps: elevator, aileron or rudder.
std::string axis_control(const std::string& axis);

/// The force step `fedsim latency --loader --axis AXIS` takes when --force is not given [N].
double default_force_n(const std::string& axis);
/// --loader: the profile's force channel the axis steps: column_force_n, wheel_force_n or pedal_force_n.
std::string axis_force_channel(const std::string& axis);

/// Throws std::invalid_argument naming the option that is out of range or not finite.
void check_latency_options(const LatencyOptions& options);

/// The profile fedsim-io flies: time_s, the axis's control (relative to the trim), one doublet per step.
std::string latency_profile_csv(const LatencyOptions& options);
/// Sim time of step k (0-based) and its signed amplitude (--loader: the force [N]).
double step_time_s(const LatencyOptions& options, int k);
double step_amplitude(const LatencyOptions& options, int k);

/// Runs the measurement; returns the exit status (0, 1 or 2 as above).
int run_latency(const LatencyOptions& options, std::ostream& out, std::ostream& err);

/// Registers `fedsim latency` on the app; its result goes to exit_code.
void add_latency_command(CLI::App& app, int& exit_code);

}  // namespace fedsim::launcher
