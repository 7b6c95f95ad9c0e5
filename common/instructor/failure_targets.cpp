#include "common/instructor/failure_targets.hpp"

#include <array>

namespace fedsim::instructor {

std::optional<FailureOwner> failure_target_owner(std::string_view t) {
  if (t.size() == 7 && t.substr(0, 6) == "engine" && t[6] >= '1' && t[6] <= '4') return FailureOwner::kFlight;
  if (t == "autopilot" || t == "autothrottle") return FailureOwner::kFlight;
  for (std::string_view n : {"nav1", "nav2", "adf", "markers", "ins", "gps"}) {
    if (t == n) return FailureOwner::kNavigation;
  }
  for (std::string_view prefix : {"station:", "station-dme:", "station-gs:", "station-markers:"}) {
    if (t.size() > prefix.size() && t.substr(0, prefix.size()) == prefix) return FailureOwner::kNavigation;
  }
  if (t == "motion") return FailureOwner::kMotion;
  if (t == "control_loading") return FailureOwner::kControlLoading;
  return std::nullopt;
}

const char* failure_targets_description() {
  return "engine1..engine4, autopilot, autothrottle (flight); nav1, nav2, adf, markers, ins, gps (denied), "
         "station:<IDENT>, station-dme:<IDENT>, station-gs:<IDENT>, station-markers:<IDENT> (navigation); "
         "motion (the motion platform: cut-off); control_loading (cut-off)";
}

}  // namespace fedsim::instructor
