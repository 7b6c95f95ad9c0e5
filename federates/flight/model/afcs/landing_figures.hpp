// The figures of an automatic landing and the limits they are judged against (the AFCS issue's,
// for a 737 on a 61 m runway): touchdown within 27 ft (8.2 m) of the centreline, sink rate below
// 6 ft/s, touchdown 200 to 2,700 ft beyond the threshold, wings level within 5 deg, stopped on
// the runway. The centreline is the runway's own (threshold to the opposite threshold), an
// independent reference to the localizer course the AFCS flies.
#pragma once

#include "common/airports/runway_table.hpp"
#include "flight/model/afcs/closed_loop_flight.hpp"

#include <string>
#include <vector>

namespace fedsim::flight::afcs {

/// A runway's centreline: from its landing threshold to the opposite end's threshold, in the
/// local tangent plane at the landing threshold (GeographicLib LocalCartesian).
class RunwayCentreline {
 public:
  /// Throws std::invalid_argument when the two points coincide.
  RunwayCentreline(double threshold_lat_rad, double threshold_lon_rad, double far_lat_rad, double far_lon_rad);
  /// The landing end `runway` of `airport` and its opposite end in the table (e.g. KSFO 28R and
  /// 10L: designators differ by 18, L and R swapped); throws std::invalid_argument when either is missing.
  static RunwayCentreline from_table(const RunwayTable& table, const std::string& airport, const std::string& runway);
  double length_m() const { return length_m_; }
  /// Distance beyond the threshold along the centreline [m].
  double beyond_threshold_m(double lat_rad, double lon_rad) const;
  /// Distance left of the centreline, seen landing [m].
  double left_m(double lat_rad, double lon_rad) const;

 private:
  void plane_coordinates(double lat_rad, double lon_rad, double& east_m, double& north_m) const;
  double lat0_deg_ = 0.0, lon0_deg_ = 0.0;
  double along_east_ = 0.0, along_north_ = 0.0;  // unit vector of the landing direction
  double length_m_ = 0.0;
};

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
