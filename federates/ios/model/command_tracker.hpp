// Every command the instructor sends is shown as confirmed only by what the federation then
// reports (seed 9.4.5: the instructor must see the simulator do it, not the page assume it):
//   run / freeze / reset  the frame tick's run state (reset: sim time back to zero)
//   reposition            the aircraft state within 1 km (lateral) of where it was sent
//   weather               the wind at the aircraft within 25 % (at least 3 m/s) of the wind
//                         asked for at that height
//   fail / restore X      the report of X's owner: an engine's running flag, a receiver's
//                         validity, the autopilot's failed flag, motion / loader status
//   time of day, tune, snapshot  a field that reports it where there is one (visual status,
//                         navigation tuning); otherwise "sent" (nothing reports it)
// A command not confirmed within the timeout is "unconfirmed". Pure: the host feeds what it
// observed through a FieldLookup (topic, flattened field) -> value.
#pragma once

#include "common/instructor/instructor_request.hpp"

#include <cstdint>
#include <deque>
#include <functional>
#include <optional>
#include <string>
#include <vector>

namespace fedsim::ios {

using FieldLookup = std::function<std::optional<double>(const std::string& topic, const std::string& field)>;

/// Where a runway reposition should put the aircraft (from the navigation database).
struct ExpectedPosition {
  double latitude_rad = 0.0;
  double longitude_rad = 0.0;
};

enum class CommandStatus { kPending, kConfirmed, kUnconfirmed, kSent };

struct TrackedCommand {
  std::uint32_t sequence = 0;
  std::string text;             // describe(request)
  CommandStatus status = CommandStatus::kPending;
  double sent_s = 0.0;          // host clock when sent [s]
  double settled_s = 0.0;       // when confirmed / given up [s]
  std::string evidence;         // what confirmed it ("run_state = FREEZE")
};

const char* status_name(CommandStatus s);

class CommandTracker {
 public:
  explicit CommandTracker(double timeout_s = 5.0, std::size_t keep = 50);

  /// Records a command sent at `now_s`; `expected` for runway repositions. The lookup is
  /// read now for the state it must change from (sim time for a reset).
  void sent(std::uint32_t sequence, const instructor::InstructorRequest& request, double now_s,
            const FieldLookup& lookup, std::optional<ExpectedPosition> expected = std::nullopt);
  /// Checks the pending commands against what is observed now; returns those that settled.
  std::vector<TrackedCommand> update(double now_s, const FieldLookup& lookup);
  /// The newest commands first.
  const std::deque<TrackedCommand>& commands() const { return commands_; }

 private:
  struct Pending {
    instructor::InstructorRequest request;
    std::optional<ExpectedPosition> expected;
    std::optional<double> sim_time_at_send_s;
  };
  std::optional<std::string> confirmation(const Pending& p, const FieldLookup& lookup) const;

  double timeout_s_;
  std::size_t keep_;
  std::deque<TrackedCommand> commands_;
  std::deque<Pending> pending_;  // parallel to commands_
};

}  // namespace fedsim::ios
