// Switch with fader (the autopilot "fader" or "synchroniser"): passes the selected source and,
// when the selection changes, fades from the old output to the new source over fade_time_s so
// that the output never steps on a mode change.
//
// On a change of source at step n the offset d = y_{n-1} - u_n (what the output would jump by)
// is captured and then removed linearly over M = ceil(T_fade/dt) steps:  y = u + d (1 - k/M),
// k = 1 .. M; from then on y = u exactly. Each step therefore moves the output by the new
// source's own change plus |d|/M <= |d| dt/T_fade: the fade's rate |d|/T_fade at most.
// The new source is followed from the first step (its dynamics are not attenuated); a further
// change during a fade captures a fresh offset from the current output, so the output stays
// continuous whatever the switching.
//
// Sources are named by any int the caller chooses (a mode enum, an index). Sampled every dt_s.
#pragma once

namespace fedsim::control {

class Fader {
 public:
  /// fade_time_s >= dt_s (a shorter fade would be a step), both finite and positive.
  Fader(double fade_time_s, double dt_s);

  /// The output for the selected source and its value this step (finite). Before the first
  /// step or reset there is no previous output: the first step passes its input through.
  double step(int source, double input);
  /// No fade in progress; the output is `output` and `source` the selected source.
  void reset(int source, double output);

  double output() const { return output_; }
  int source() const { return source_; }
  /// True while an offset is still being faded out.
  bool fading() const { return steps_left_ > 0; }
  double fade_time_s() const { return fade_time_s_; }
  /// M = ceil(fade_time_s/dt_s): the steps a fade lasts.
  int fade_steps() const { return fade_steps_; }

 private:
  double fade_time_s_;
  int fade_steps_;       // M
  int steps_left_ = 0;   // of the current fade; the share of d still applied is steps_left_/M
  double offset_ = 0.0;  // d: old output - new input at the change
  double output_ = 0.0;
  int source_ = 0;
  bool started_ = false;
};

}  // namespace fedsim::control
