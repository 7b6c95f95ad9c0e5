#include "ios/model/replay_clock.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace fedsim::ios {

ReplayClock::ReplayClock(std::vector<double> times_s) : times_(std::move(times_s)) {
  if (times_.empty()) throw std::invalid_argument("replay: nothing recorded to replay");
  for (std::size_t i = 0; i < times_.size(); ++i) {
    if (!std::isfinite(times_[i]) || (i > 0 && times_[i] < times_[i - 1])) {
      throw std::invalid_argument("replay: sample " + std::to_string(i) + "'s sim time goes back or is not finite");
    }
  }
  anchor_replay_s_ = times_.front();
}

void ReplayClock::play(double now_s, double speed) {
  if (!(std::isfinite(speed) && speed > 0.0 && speed <= 100.0)) {
    throw std::invalid_argument("replay: speed must be within (0, 100]");
  }
  anchor_replay_s_ = position_s(now_s);
  anchor_wall_s_ = now_s;
  speed_ = speed;
  playing_ = true;
}

void ReplayClock::pause(double now_s) {
  anchor_replay_s_ = position_s(now_s);
  anchor_wall_s_ = now_s;
  playing_ = false;
}

void ReplayClock::seek(double now_s, double t_s) {
  if (!std::isfinite(t_s)) throw std::invalid_argument("replay: seek time is not finite");
  anchor_replay_s_ = std::clamp(t_s, start_s(), end_s());
  anchor_wall_s_ = now_s;
}

double ReplayClock::position_s(double now_s) const {
  const double t = playing_ ? anchor_replay_s_ + speed_ * (now_s - anchor_wall_s_) : anchor_replay_s_;
  return std::clamp(t, start_s(), end_s());
}

std::size_t ReplayClock::due(double now_s) const {
  const double t = position_s(now_s);
  // The last sample whose time is <= t (upper_bound - 1; the first is always due).
  const auto it = std::upper_bound(times_.begin(), times_.end(), t);
  return it == times_.begin() ? 0 : static_cast<std::size_t>(it - times_.begin()) - 1;
}

}  // namespace fedsim::ios
