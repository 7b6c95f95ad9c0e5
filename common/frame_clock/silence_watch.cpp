#include "common/frame_clock/silence_watch.hpp"

#include <algorithm>
#include <cmath>

namespace fedsim::timing {

std::uint64_t SilenceWatch::first_sample_frames_for(std::uint64_t limit_frames, bool realtime, double frame_period_s) {
  if (!realtime || !(frame_period_s > 0.0) || !std::isfinite(frame_period_s)) return limit_frames;
  const double grace = std::ceil(kJoinGraceS / frame_period_s);
  return std::max<std::uint64_t>(limit_frames, static_cast<std::uint64_t>(std::min(grace, 1e9)));
}

SilenceWatch::Event SilenceWatch::observe(std::uint64_t frame, bool matched, bool updated) {
  if (!matched) {
    watching_ = false;
    written_ = false;
    silent_ = false;
    quiet_frames_ = 0;
    return Event::kNone;
  }
  if (!watching_ || updated) {
    watching_ = true;
    written_ = written_ || updated;
    since_frame_ = frame;
    quiet_frames_ = 0;
    if (updated && silent_) {
      silent_ = false;
      return Event::kResumed;
    }
    return Event::kNone;
  }
  quiet_frames_ = frame > since_frame_ ? frame - since_frame_ : 0;
  const std::uint64_t limit = written_ ? limit_frames_ : first_sample_frames_;
  if (limit_frames_ != 0 && !silent_ && quiet_frames_ >= limit) {
    silent_ = true;
    return Event::kSilent;
  }
  return Event::kNone;
}

}  // namespace fedsim::timing
