#include "flight/model/afcs/vor_guidance.hpp"

#include "flight/model/afcs/lateral_guidance.hpp"

#include <algorithm>
#include <cmath>

namespace fedsim::flight::afcs {

VorGuidance::VorGuidance(const VorGains& gains, double dt_s)
    : gains_(gains),
      dt_s_(dt_s),
      deviation_(gains.deviation_filter_s, dt_s),
      deviation_rate_(gains.erratic_filter_s, dt_s) {}

void VorGuidance::reset() {
  was_valid_ = false;
  dme_was_valid_ = false;
  nominal_started_ = false;
  last_to_from_ = VorToFrom::kOff;
  estimate_ = VorEstimate{};
}

void VorGuidance::station_passed() {
  nominal_distance_m_ = gains_.min_nominal_distance_m;
  nominal_started_ = true;
}

const VorEstimate& VorGuidance::step(const AfcsVorSignals& vor, double ground_speed_mps, double track_true_rad) {
  // A receiver retuned, failed or out of range: the next VOR received starts a new schedule
  // (a cone-of-confusion flag is the same station, and keeps it).
  if (!vor.tuned || (!vor.valid && !vor.cone_of_confusion)) nominal_started_ = false;
  update_distance(vor, ground_speed_mps, track_true_rad);
  estimate_.valid = vor.valid;
  estimate_.passed_station = false;
  if (!vor.valid) {
    estimate_.deviation = 0.0;
    estimate_.cross_track_left_m = 0.0;
    estimate_.erratic = false;
    was_valid_ = false;
    return estimate_;
  }
  update_deviation(vor);
  estimate_.course_true_rad = vor.course_true_rad;
  estimate_.cross_track_left_m =
      vor_cross_track_left_m(estimate_.deviation, vor.full_scale_rad, estimate_.distance_m);
  estimate_.passed_station = last_to_from_ == VorToFrom::kTo && vor.to_from == VorToFrom::kFrom;
  if (vor.to_from != VorToFrom::kOff) last_to_from_ = vor.to_from;
  was_valid_ = true;
  return estimate_;
}

void VorGuidance::update_deviation(const AfcsVorSignals& vor) {
  if (!was_valid_) {
    // The first valid reading (again): no rate from the gap, no lag from stale values.
    deviation_.reset(vor.deviation);
    deviation_rate_.reset(0.0);
    previous_deviation_ = vor.deviation;
  }
  estimate_.deviation = deviation_.step(vor.deviation);
  const double rate = deviation_rate_.step((vor.deviation - previous_deviation_) / dt_s_);
  previous_deviation_ = vor.deviation;
  estimate_.erratic = std::abs(rate) > gains_.erratic_rate_per_s;
}

void VorGuidance::update_distance(const AfcsVorSignals& vor, double ground_speed_mps, double track_true_rad) {
  const bool dme = vor.tuned && vor.dme_valid;
  if (dme) {
    estimate_.distance_m = vor.dme_slant_range_m;
    estimate_.distance_from_dme = true;
    dme_was_valid_ = true;
    return;
  }
  if (dme_was_valid_) {
    // The DME lost: carry on from its last distance.
    nominal_distance_m_ = estimate_.distance_m;
    nominal_started_ = true;
  } else if (!nominal_started_) {
    nominal_distance_m_ = gains_.nominal_distance_m;
    nominal_started_ = true;
  }
  dme_was_valid_ = false;
  if (vor.valid && vor.to_from != VorToFrom::kOff) {
    // Along the course, TO closes on the station and FROM opens from it.
    const double along_mps = ground_speed_mps * std::cos(wrap_angle_rad(track_true_rad - vor.course_true_rad));
    nominal_distance_m_ += (vor.to_from == VorToFrom::kTo ? -along_mps : along_mps) * dt_s_;
  }
  nominal_distance_m_ = std::clamp(nominal_distance_m_, gains_.min_nominal_distance_m, gains_.max_nominal_distance_m);
  estimate_.distance_m = nominal_distance_m_;
  estimate_.distance_from_dme = false;
}

}  // namespace fedsim::flight::afcs
