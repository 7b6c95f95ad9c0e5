// The VOR side of VOR/LOC, one call per frame (stateful: filters and the distance estimate).
//
// Input: NAV1's VOR reading (AfcsVorSignals) and the ground speed and track. Output (VorEstimate):
//   - the deviation low-passed over VorGains::deviation_filter_s (a real beam's noise and
//     scalloping; the lag is in the capture lead, lateral_guidance vor_course_law());
//   - the distance from the station: the DME's slant range when received (it overstates the
//     ground distance by about (h/d)^2/2 for a height h above the station: 0.6 % at 15 NM, 5 %
//     at 5 NM from 10,000 ft; the track law's gain by as much, and nearer the station the
//     course is held: OVER STATION),
//     else the nominal schedule: VorGains::nominal_distance when the VOR is first received (the
//     last DME distance when the DME is lost), dead-reckoned along the course (TO: closing,
//     FROM: opening), within [min, max] and restarted at the minimum after a station passage.
//     Without DME the law's gain is off by nominal / true distance: the capture lead and the
//     track law then act as if the aircraft were that much nearer or farther (README.md);
//   - the cross track y = d sin(deviation x full scale) (lateral_guidance);
//   - the cues of a station passage: the deviation moving faster than VorGains::erratic_rate
//     (low-passed; a 45 deg intercept at 5 NM and 290 kt moves it at 0.02 full scale/s) or the
//     TO/FROM flag turning from TO to FROM between valid readings.
// Nothing from a flagged reading is used: the estimate keeps the last valid course and drops
// the rest; the filters restart on the next valid reading.
#pragma once

#include "common/control/first_order_lag.hpp"
#include "flight/model/afcs/afcs_inputs.hpp"
#include "flight/model/afcs/afcs_parameters.hpp"

namespace fedsim::flight::afcs {

struct VorEstimate {
  bool valid = false;               // a valid VOR reading this frame
  double deviation = 0.0;           // low-passed, -1..1 of full scale [-]
  double distance_m = 0.0;          // from the station: DME or nominal [m]
  bool distance_from_dme = false;
  double cross_track_left_m = 0.0;  // + = left of the course (fly right) [m]
  double course_true_rad = 0.0;     // the last valid course [rad]
  bool erratic = false;             // the deviation moves faster than the erratic rate
  bool passed_station = false;      // TO turned FROM (this frame)
};

class VorGuidance {
 public:
  VorGuidance(const VorGains& gains, double dt_s);

  const VorEstimate& step(const AfcsVorSignals& vor, double ground_speed_mps, double track_true_rad);
  /// Over the station: the nominal distance restarts at its minimum.
  void station_passed();
  const VorEstimate& estimate() const { return estimate_; }
  /// As constructed (no VOR received yet).
  void reset();

 private:
  void update_distance(const AfcsVorSignals& vor, double ground_speed_mps, double track_true_rad);
  void update_deviation(const AfcsVorSignals& vor);

  VorGains gains_;
  double dt_s_;
  control::FirstOrderLag deviation_;
  control::FirstOrderLag deviation_rate_;
  double previous_deviation_ = 0.0;
  bool was_valid_ = false;
  bool dme_was_valid_ = false;
  bool nominal_started_ = false;
  double nominal_distance_m_ = 0.0;
  VorToFrom last_to_from_ = VorToFrom::kOff;  // of the last valid reading
  VorEstimate estimate_;
};

}  // namespace fedsim::flight::afcs
