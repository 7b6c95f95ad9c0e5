// Which fedsim/sim_command samples are settings (kept for late joiners) and which are events,
// the command holder's memory of the current settings, and the receiver's filter that makes a
// re-delivered setting harmless. Pure logic on the IDL type: no DDS entity here.
//
// Why: fedsim/sim_command is transient-local, so a late joiner gets the latest sample of each
// (kind, target) instance, but only from writers that still exist; `fedsim command` exits once
// its command is acknowledged, and with it its copy. A holder (the timing federate, always
// there) republishes every setting it sees, unchanged (same issuer, sequence number and
// payload), from its own transient-local writer. Running federates then receive each setting
// twice (the original and the holder's copy); the filter drops the second one, so a setting is
// applied once (applying a weather twice, for one, re-seeds the turbulence: runs would differ).
#pragma once

#include "fedsim/msg/command.h"

#include <map>
#include <string>
#include <utility>
#include <vector>

namespace fedsim::runtime {

/// A setting describes the federation's current state and stays true until replaced: weather,
/// a failure (per target system), radio tuning (per aircraft), time of day. An event acts once
/// when it is issued and must not be replayed to a federate that starts later: a reposition, a
/// snapshot, shutdown, and the run state (every frame tick carries the run state, so a late
/// joiner has it from its first tick; a replayed reset would reset again).
bool is_setting(const msg::SimCommand& command);

/// The latest setting of each (kind, target), as the holder republishes them.
class SettingHolder {
 public:
  /// Takes a received command; true if it is a setting that differs from the one held for its
  /// kind and target (the holder then republishes it). Events, and a setting already held (the
  /// holder's own copy coming back, or a duplicate), return false.
  bool offer(const msg::SimCommand& command);
  /// The held settings, by kind and target.
  std::vector<msg::SimCommand> held() const;
  std::size_t size() const { return held_.size(); }

 private:
  std::map<std::pair<int, std::string>, msg::SimCommand> held_;
};

/// A receiver's filter: false for a setting identical (issuer, sequence number and payload) to
/// the last one delivered for its kind and target (a re-delivery, e.g. the holder's copy of a
/// command the receiver already has); true for everything else. Events always pass: two equal
/// repositions are two repositions.
class RedeliveryFilter {
 public:
  bool first_delivery(const msg::SimCommand& command);
  std::size_t dropped() const { return dropped_; }

 private:
  std::map<std::pair<int, std::string>, msg::SimCommand> last_;
  std::size_t dropped_ = 0;
};

}  // namespace fedsim::runtime
