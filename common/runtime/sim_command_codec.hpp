// An instructor request (common/instructor, checked and in SI) as the fedsim/sim_command sample
// that carries it, and back: `fedsim command`, the instructor station and scenarios send through
// to_sim_command(); the instructor station shows the federation's current settings (the
// transient-local history of the topic) through from_sim_command().
#pragma once

#include "common/instructor/instructor_request.hpp"
#include "fedsim/msg/command.h"

#include <optional>

namespace fedsim::runtime {

/// The IDL run state of the frame clock's (the tick and the command carry the same three).
msg::RunState to_msg(timing::RunState state);
/// And back (a state this build does not know is FREEZE: the safe one).
timing::RunState from_msg(msg::RunState state);

/// The sample for `request` (kind, target and payload; issuer and sequence number left to the
/// sender). A snapshot request is stamped with the sender's CLOCK_REALTIME now.
msg::SimCommand to_sim_command(const instructor::InstructorRequest& request);

/// The request a sample carries; nullopt for a kind this build does not know.
std::optional<instructor::InstructorRequest> from_sim_command(const msg::SimCommand& command);

}  // namespace fedsim::runtime
