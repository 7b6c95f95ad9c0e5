// When an expected federate counts as lost, when it counts as back, and the record of both
// (pure logic, no DDS, no clock: times are passed in).
//
// Silence: a federate is lost once a tick it has not acknowledged has been outstanding for the
// acknowledgement timeout, measured from the first such tick (the first one published after
// its latest acknowledgement), never from the latest tick: in realtime a tick goes out every
// frame, so the latest one is always recent and a stopped federate was never reported. In
// lockstep the two are the same tick; a paced lockstep's idle time between a frame's completion
// and the next tick does not count against anyone.
//
// Rejoin: a lost federate that reports itself again (status READY or RUNNING: a restarted
// process, or one that was stopped and continued) is expected again from the next tick; a
// federate whose process was replaced (its status shows a new pid) before it was found silent
// is recorded as lost and rejoined at once.
#pragma once

#include <cstdint>
#include <map>
#include <string>
#include <vector>

namespace fedsim::timing {

struct MembershipEvent {
  enum class Kind { kLost, kRejoined };
  Kind kind;
  std::string federate;
  std::uint64_t frame;   // lost: the frame it was waited for; rejoined: its first frame back
  double t_s;            // seconds since the run started
  std::string why;       // lost: the reason
};

class LossWatch {
 public:
  explicit LossWatch(std::uint64_t ack_timeout_ns) : timeout_ns_(ack_timeout_ns) {}

  /// A new tick (not a repeat) went out that these federates must acknowledge: the clock of each
  /// one that has nothing outstanding starts now.
  void tick_published(const std::vector<std::string>& expected, std::uint64_t now_ns);
  /// An acknowledgement (of any frame) from the federate: it is alive; its clock stops.
  void acknowledged(const std::string& federate);
  /// Federates whose oldest unacknowledged tick is at least the timeout old.
  std::vector<std::string> overdue(std::uint64_t now_ns) const;
  /// How long the federate's oldest unacknowledged tick has been out (0 if none).
  std::uint64_t age_ns(const std::string& federate, std::uint64_t now_ns) const;

  /// A process reported its state: true if it is a new process of a federate seen before (its
  /// pid changed), i.e. the old one is gone, whatever the acknowledgements said.
  bool process_replaced(const std::string& federate, std::uint32_t pid);
  std::uint32_t pid_of(const std::string& federate) const;

  void record_lost(const std::string& federate, std::uint64_t frame, double t_s, std::string why);
  /// A lost federate is back; false (nothing recorded) if it is not lost.
  bool record_rejoined(const std::string& federate, std::uint64_t frame, double t_s);
  bool is_lost(const std::string& federate) const;

  const std::vector<MembershipEvent>& events() const { return events_; }
  /// Every loss in order (a federate lost twice appears twice).
  std::vector<std::string> lost() const;
  std::vector<std::string> rejoined() const;
  /// Lost and not back.
  std::vector<std::string> still_lost() const;

 private:
  std::uint64_t timeout_ns_;
  std::map<std::string, std::uint64_t> outstanding_since_ns_;  // federate -> first unacked tick
  std::map<std::string, std::uint32_t> pids_;
  std::map<std::string, bool> lost_now_;
  std::vector<MembershipEvent> events_;
};

}  // namespace fedsim::timing
