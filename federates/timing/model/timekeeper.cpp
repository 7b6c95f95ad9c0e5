#include "timing/model/timekeeper.hpp"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <stdexcept>

namespace fedsim::timing {

namespace {
constexpr std::uint64_t kNsPerS = 1'000'000'000ull;
// Lockstep: how often the clock looks at overdue acknowledgements and losses while it waits.
constexpr std::uint64_t kLockstepPollNs = 10'000'000ull;
// Realtime: after the last tick, how long its acknowledgements may take (for the statistics).
constexpr std::uint64_t kRealtimeDrainNs = 200'000'000ull;

double checked(double value, const char* name, double min, double max, bool min_open = false) {
  const bool ok = std::isfinite(value) && (min_open ? value > min : value >= min) && value <= max;
  if (!ok) {
    char text[160];
    std::snprintf(text, sizeof(text), "timing: %s %g is not finite or outside %s%g, %g]", name, value,
                  min_open ? "(" : "[", min, max);
    throw std::invalid_argument(text);
  }
  return value;
}

std::uint64_t to_ns(double seconds) { return static_cast<std::uint64_t>(seconds * kNsPerS); }

std::string join_names(const std::vector<std::string>& names) {
  std::string out;
  for (const auto& n : names) out += (out.empty() ? "" : ",") + n;
  return out;
}
}  // namespace

Timekeeper::Timekeeper(TimekeeperSettings settings)
    : settings_(std::move(settings)),
      period_ns_(static_cast<std::uint64_t>(kNsPerS / checked(settings_.rate_hz, "rate_hz", 0.0, 100000.0, true))),
      resend_ns_(to_ns(checked(settings_.resend_after_s, "resend_after_s", 0.0, 3600.0, true))),
      tracker_(settings_.expect),
      run_control_(1.0 / settings_.rate_hz, settings_.start),
      loss_watch_(to_ns(checked(settings_.ack_timeout_s, "ack_timeout_s", 0.0, 3600.0, true))) {
  checked(settings_.scale, "scale", 0.0, 1000.0);
  checked(settings_.join_timeout_s, "join_timeout_s", 0.0, 86400.0, true);
  checked(settings_.settle_s, "settle_s", 0.0, 60.0);
  checked(settings_.duration_s, "duration_s", 0.0, 1e9);
  if (settings_.start == RunState::kReset) throw std::invalid_argument("timing: the first frame is run or freeze");
}

// ---- What arrives --------------------------------------------------------------------------

bool Timekeeper::is_member(const std::string& federate) const {
  return std::find(settings_.expect.begin(), settings_.expect.end(), federate) != settings_.expect.end();
}

void Timekeeper::status(const std::string& federate, MemberState state, std::uint32_t pid,
                        const std::string& message, std::uint64_t now_ns) {
  const bool member = is_member(federate);
  switch (state) {
    case MemberState::kReady:
    case MemberState::kRunning: {
      ready_.insert(federate);
      const std::uint32_t old_pid = loss_watch_.pid_of(federate);
      const bool replaced = loss_watch_.process_replaced(federate, pid);
      if (!member || !started_ || stopping_) break;
      // A new process under the name: the old one is gone, even if it was never found silent
      // (a quick restart answers the repeated tick before the acknowledgement timeout).
      if (replaced && !loss_watch_.is_lost(federate)) {
        mark_lost(federate, "its process (pid " + std::to_string(old_pid) + ") was replaced", now_ns);
      }
      if (loss_watch_.is_lost(federate)) {
        rejoin(federate, replaced ? "new process pid " + std::to_string(pid)
                                  : "reports again, pid " + std::to_string(pid),
               now_ns);
      }
      break;
    }
    case MemberState::kStopping:
    case MemberState::kFailed:
      // A member that stops because the federation is told to stop is not lost (the clock may
      // see its status before the SHUTDOWN command itself).
      if (member && !loss_watch_.is_lost(federate) && started_ && !stopping_ &&
          message.rfind("shutdown command", 0) != 0) {
        mark_lost(federate, state == MemberState::kFailed ? "failed: " + message : "stopped", now_ns);
      }
      ready_.erase(federate);
      break;
    case MemberState::kStarting:
    case MemberState::kLost:  // a report about it (the clock's own), not from it
      break;
  }
}

Timekeeper::Ack Timekeeper::acknowledge(const std::string& federate, std::uint64_t frame,
                                        std::uint64_t now_ns) {
  if (!started_) return Ack::kNothing;
  if (!loss_watch_.is_lost(federate)) loss_watch_.acknowledged(federate);
  if (!tracker_.acknowledge(federate, frame)) return Ack::kNothing;
  summary_.all_acked.add_ns(now_ns - tick_issued_ns_);
  if (lockstep() && settings_.scale <= 0.0 && !should_stop(now_ns)) return Ack::kTickNow;
  return Ack::kCompleted;
}

void Timekeeper::liveliness_lost(const std::string& federate, std::uint64_t now_ns) {
  if (!started_ || stopping_) return;
  if (tracker_.expects(federate) && !loss_watch_.is_lost(federate)) {
    mark_lost(federate, "liveliness lost (process gone or hung)", now_ns);
  }
}

void Timekeeper::stop(std::string reason) {
  if (stopping_) return;
  stopping_ = true;
  if (stop_reason_.empty()) stop_reason_ = std::move(reason);
}

void Timekeeper::mark_lost(const std::string& federate, const std::string& why, std::uint64_t now_ns) {
  summary_.lost.push_back(federate);
  loss_watch_.record_lost(federate, tracker_.frame(), run_time_s(now_ns), why);
  const bool completed = tracker_.remove(federate);
  reports_.push_back({Report::Kind::kLost, federate, tracker_.frame(), why, loss_watch_.pid_of(federate), 0});
  if (settings_.stop_on_lost) {
    stopping_ = true;
    stop_reason_ = "federate " + federate + " lost";
    exit_code_ = 1;
  }
  if (completed) summary_.all_acked.add_ns(now_ns - tick_issued_ns_);
}

void Timekeeper::rejoin(const std::string& federate, const std::string& how, std::uint64_t now_ns) {
  tracker_.readmit(federate);
  const std::uint64_t first_frame = tracker_.frame() + 1;
  if (!loss_watch_.record_rejoined(federate, first_frame, run_time_s(now_ns))) return;
  summary_.rejoined.push_back(federate);
  reports_.push_back({Report::Kind::kRejoined, federate, first_frame, how, 0, 0});
}

/// Silence, measured from the first tick a member did not acknowledge (model/loss_watch.hpp).
void Timekeeper::check_ack_timeouts(std::uint64_t now_ns) {
  for (const auto& name : loss_watch_.overdue(now_ns)) {
    if (!tracker_.expects(name)) continue;
    char why[96];
    std::snprintf(why, sizeof(why), "no acknowledgement for %.2f s (--ack-timeout %g s)",
                  loss_watch_.age_ns(name, now_ns) * 1e-9, settings_.ack_timeout_s);
    mark_lost(name, why, now_ns);
  }
}

// ---- The join ------------------------------------------------------------------------------

std::vector<std::string> Timekeeper::not_ready() const {
  std::vector<std::string> missing;
  for (const auto& name : settings_.expect) {
    if (!ready_.count(name)) missing.push_back(name);
  }
  return missing;
}

Timekeeper::Join Timekeeper::join(std::uint64_t now_ns, int tick_readers, int ack_writers) {
  if (join_started_ns_ == 0) join_started_ns_ = now_ns;
  if (settle_until_ns_ == 0) {
    const auto n = static_cast<int>(settings_.expect.size());
    if (not_ready().empty() && tick_readers >= n && ack_writers >= n) {
      // Discovery is two-sided: the other halves of the matches need a moment so that the first
      // frames' samples reach every reader.
      settle_until_ns_ = now_ns + to_ns(settings_.settle_s);
    } else if (now_ns - join_started_ns_ > to_ns(settings_.join_timeout_s)) {
      return Join::kTimedOut;
    } else {
      return Join::kWaiting;
    }
  }
  return now_ns >= settle_until_ns_ ? Join::kReady : Join::kSettling;
}

// ---- The run -------------------------------------------------------------------------------

void Timekeeper::start(std::uint64_t now_ns) {
  started_ = true;
  start_ns_ = now_ns;
}

double Timekeeper::run_time_s(std::uint64_t now_ns) const {
  return start_ns_ == 0 || now_ns < start_ns_ ? 0.0 : (now_ns - start_ns_) * 1e-9;
}

bool Timekeeper::frames_exhausted() const {
  return settings_.max_frames != 0 && ticks_issued_ >= settings_.max_frames;
}

bool Timekeeper::should_stop(std::uint64_t now_ns) const {
  if (stopping_ || frames_exhausted()) return true;
  return settings_.duration_s > 0 && started_ && now_ns - start_ns_ >= to_ns(settings_.duration_s);
}

TickFields Timekeeper::issue_tick(std::uint64_t now_ns) {
  const TickFields fields = run_control_.next_tick();
  tracker_.start_frame(fields.frame);
  tick_issued_ns_ = now_ns;
  loss_watch_.tick_published(tracker_.expected(), now_ns);
  last_resend_ns_ = now_ns;
  ++ticks_issued_;
  summary_.frames = ticks_issued_;
  return fields;
}

Timekeeper::Due Timekeeper::wake(std::uint64_t now_ns) {
  if (!started_) return {false, false, false, now_ns + kLockstepPollNs};
  return lockstep() ? wake_lockstep(now_ns) : wake_realtime(now_ns);
}

Timekeeper::Due Timekeeper::wake_realtime(std::uint64_t now_ns) {
  Due due;
  if (drain_until_ns_ == 0 && should_stop(now_ns)) drain_until_ns_ = now_ns + kRealtimeDrainNs;
  if (drain_until_ns_ != 0) {  // the run is over: the last frame's acknowledgements may still come
    due.finished = tracker_.complete() || now_ns >= drain_until_ns_;
    due.next_ns = drain_until_ns_;
    return due;
  }
  const std::uint64_t deadline = start_ns_ + (deadlines_passed_ + 1) * period_ns_;
  if (now_ns < deadline) {
    due.next_ns = deadline;
    return due;
  }
  if (deadlines_passed_ > 0 && !tracker_.complete()) {
    ++summary_.overruns;
    if (summary_.overruns <= 10 || summary_.overruns % 100 == 0) {
      reports_.push_back({Report::Kind::kOverrun, "", tracker_.frame(), join_names(tracker_.missing()), 0,
                          summary_.overruns});
    }
  }
  // Every frame, not only on an overrun: the frame is complete without a lost member.
  check_ack_timeouts(now_ns);
  if (deadlines_passed_ > 0) summary_.period_error.add_ns(now_ns - deadline);
  ++deadlines_passed_;
  due.tick = true;
  due.next_ns = start_ns_ + (deadlines_passed_ + 1) * period_ns_;
  return due;
}

Timekeeper::Due Timekeeper::wake_lockstep(std::uint64_t now_ns) {
  Due due;
  due.next_ns = now_ns + kLockstepPollNs;
  if (tracker_.complete()) {
    if (should_stop(now_ns)) {
      due.finished = true;
      return due;
    }
    if (settings_.scale > 0.0) {
      // Paced lockstep: tick n is due at n * period / scale after the start.
      const double period_s = 1.0 / settings_.rate_hz;
      const auto paced = start_ns_ + static_cast<std::uint64_t>(static_cast<double>(ticks_issued_) * period_s /
                                                                settings_.scale * kNsPerS);
      if (now_ns < paced) {
        due.next_ns = paced;
        return due;
      }
    }
    // Frames completed by an acknowledgement had their next tick at once (scale 0); this is for
    // the others (paced, or completed by dropping a lost member).
    due.tick = true;
    return due;
  }
  if (should_stop(now_ns) && !frames_exhausted()) {
    due.finished = true;
    return due;
  }
  if (now_ns - last_resend_ns_ >= resend_ns_) {
    last_resend_ns_ = now_ns;
    ++summary_.resent_ticks;
    due.resend = true;
  }
  check_ack_timeouts(now_ns);
  if (tracker_.complete()) due.next_ns = now_ns;  // a loss completed the frame: tick at once
  return due;
}

void Timekeeper::finish(std::uint64_t now_ns) {
  stopping_ = true;
  if (finished_) return;
  finished_ = true;
  if (started_ && now_ns > start_ns_) summary_.wall_s = (now_ns - start_ns_) * 1e-9;
}

std::vector<Report> Timekeeper::take_reports() {
  std::vector<Report> out;
  out.swap(reports_);
  return out;
}

TimingSummary Timekeeper::summary() const {
  TimingSummary s = summary_;
  s.still_lost = loss_watch_.still_lost();
  s.events = loss_watch_.events();
  return s;
}

std::string Timekeeper::summary_json(const std::string& federate, std::size_t held_settings) const {
  const TimingSummary s = summary();
  nlohmann::json j;
  j["federate"] = federate;
  j["mode"] = lockstep() ? "lockstep" : "realtime";
  j["rate_hz"] = settings_.rate_hz;
  j["frames"] = s.frames;
  j["wall_s"] = s.wall_s;
  j["frames_per_s"] = s.wall_s > 0 ? s.frames / s.wall_s : 0.0;
  j["overruns"] = s.overruns;
  j["resent_ticks"] = s.resent_ticks;
  j["lost"] = s.lost;
  j["rejoined"] = s.rejoined;
  j["still_lost"] = s.still_lost;
  j["ack_timeout_s"] = settings_.ack_timeout_s;
  j["membership"] = nlohmann::json::array();
  for (const auto& e : s.events) {
    nlohmann::json event = {{"event", e.kind == MembershipEvent::Kind::kLost ? "lost" : "rejoined"},
                            {"federate", e.federate},
                            {"frame", e.frame},
                            {"t_s", e.t_s}};
    if (!e.why.empty()) event["why"] = e.why;
    j["membership"].push_back(event);
  }
  j["held_settings"] = held_settings;
  j["all_acked_us"] = {{"p50", s.all_acked.percentile_us(50)},
                       {"p99", s.all_acked.percentile_us(99)},
                       {"max", s.all_acked.max_us()},
                       {"count", s.all_acked.count()}};
  j["period_error_us"] = {{"p50", s.period_error.percentile_us(50)},
                          {"p99", s.period_error.percentile_us(99)},
                          {"max", s.period_error.max_us()}};
  return j.dump();
}

}  // namespace fedsim::timing
