#include "common/frame_clock/silence_watch.hpp"

namespace fedsim::timing {

SilenceWatch::Event SilenceWatch::observe(std::uint64_t frame, bool matched, bool updated) {
  if (!matched) {
    watching_ = false;
    silent_ = false;
    quiet_frames_ = 0;
    return Event::kNone;
  }
  if (!watching_ || updated) {
    watching_ = true;
    since_frame_ = frame;
    quiet_frames_ = 0;
    if (updated && silent_) {
      silent_ = false;
      return Event::kResumed;
    }
    return Event::kNone;
  }
  quiet_frames_ = frame > since_frame_ ? frame - since_frame_ : 0;
  if (limit_frames_ != 0 && !silent_ && quiet_frames_ >= limit_frames_) {
    silent_ = true;
    return Event::kSilent;
  }
  return Event::kNone;
}

}  // namespace fedsim::timing
