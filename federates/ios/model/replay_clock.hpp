// The instructor station's replay timeline (seed 9.7): which recorded sample is due at a wall
// time, for a replay at `speed` times real time that may be paused, resumed and moved (seek).
// Pure: the host passes its clock; the samples' sim times must not decrease.
#pragma once

#include <cstddef>
#include <vector>

namespace fedsim::ios {

class ReplayClock {
 public:
  /// `times_s`: each sample's sim time (non-decreasing, at least one). Starts at the first
  /// sample, paused. Throws std::invalid_argument for an empty or decreasing list.
  explicit ReplayClock(std::vector<double> times_s);

  /// Runs from where it is at `speed` (> 0, finite) times real time, from wall time `now_s`.
  void play(double now_s, double speed);
  void pause(double now_s);
  /// Moves to replay time `t_s` (clamped to the recording) and keeps playing or pausing.
  void seek(double now_s, double t_s);

  /// Replay time at `now_s` (the first sample's time .. the last's).
  double position_s(double now_s) const;
  /// Index of the newest sample at or before position_s(now_s).
  std::size_t due(double now_s) const;
  bool finished(double now_s) const { return position_s(now_s) >= end_s(); }
  bool playing() const { return playing_; }
  double speed() const { return speed_; }
  double start_s() const { return times_.front(); }
  double end_s() const { return times_.back(); }

 private:
  std::vector<double> times_;
  bool playing_ = false;
  double speed_ = 1.0;
  double anchor_replay_s_ = 0.0;  // replay time at anchor_wall_s_
  double anchor_wall_s_ = 0.0;
};

}  // namespace fedsim::ios
