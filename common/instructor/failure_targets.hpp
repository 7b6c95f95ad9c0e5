// The instructor's failure targets (SimCommand COMMAND_FAILURE .target, `fedsim command fail X`)
// and the federate that owns each, stated once: a federate acts on its own targets and passes
// over the others' in silence; a name no federate owns is refused by the command line before it
// is sent, and reported by the flight federate if another writer sends it.
#pragma once

#include <optional>
#include <string_view>

namespace fedsim::instructor {

enum class FailureOwner { kFlight, kNavigation, kMotion, kControlLoading };

/// Who owns `target`: flight engine1..engine4, autopilot, autothrottle; navigation nav1, nav2,
/// adf, markers, ins, gps, station:<IDENT>, station-dme:<IDENT>, station-gs:<IDENT>,
/// station-markers:<IDENT>; motion "motion"; control loading "control_loading". nullopt: nobody.
std::optional<FailureOwner> failure_target_owner(std::string_view target);

/// The targets above in words, for --help and errors.
const char* failure_targets_description();

}  // namespace fedsim::instructor
