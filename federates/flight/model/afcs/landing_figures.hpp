// The figures of an automatic landing and the limits they are judged against (the AFCS issue's,
// for a 737 on a 61 m runway): touchdown within 27 ft (8.2 m) of the centreline, sink rate below
// 6 ft/s, touchdown 200 to 2,700 ft beyond the threshold, wings level within 5 deg, stopped on
// the runway. The centreline is the runway's own (threshold to the opposite threshold,
// fedsim::RunwayCentreline in common/airports), an independent reference to the localizer course
// the AFCS flies.
#pragma once

#include "common/airports/runway_centreline.hpp"
#include "flight/model/afcs/closed_loop_flight.hpp"

#include <string>
#include <vector>

namespace fedsim::flight::afcs {

struct LandingFigures {
  bool touched_down = false;
  Touchdown touchdown;
  double touchdown_left_of_centreline_m = 0.0;  // from the runway's centreline
  double stop_beyond_threshold_m = 0.0;         // where the aircraft came to rest (or was at the end)
  double stop_left_of_centreline_m = 0.0;
  bool stopped = false;                         // ground speed below 0.5 m/s
  double max_rollout_offset_m = 0.0;            // from the course line, on the ground
  double runway_length_m = 0.0;                 // threshold to the far end
  bool autopilot_engaged = false;               // at the end
  std::uint32_t alerts = 0;
};

struct LandingLimits {
  double max_centreline_offset_m = 27.0 * units::kFtToM;
  double max_sink_rate_mps = 6.0 * units::kFtToM;
  double min_beyond_threshold_m = 200.0 * units::kFtToM;
  double max_beyond_threshold_m = 2700.0 * units::kFtToM;
  double max_bank_rad = 5.0 * units::kDegToRad;
  double runway_half_width_m = 30.0;  // KSFO 28R: 200 ft wide
};

LandingFigures landing_figures(const ClosedLoopFlight& flight, const RunwayCentreline& runway);

/// Each limit the landing broke, in words ("sink rate 6.4 ft/s > 6.0"); empty: within them all.
std::vector<std::string> limit_violations(const LandingFigures& figures, const LandingLimits& limits = {});

}  // namespace fedsim::flight::afcs
