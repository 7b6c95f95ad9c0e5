#include "nav/model/radio/adf_radio.hpp"

#include "common/radio/radio_geometry.hpp"
#include "common/radio/station_checks.hpp"

#include <limits>

namespace fedsim::nav {

AdfRadio::AdfRadio(const radio::StationSource& source, const radio::StationOutages& outages)
    : source_(&source), outages_(&outages) {}

AdfReading AdfRadio::receive(std::uint32_t frequency_khz, const radio::AircraftPose& pose) const {
  AdfReading best;
  if (failed_) {
    best.status = radio::SignalStatus::kReceiverFailed;
    return best;
  }
  if (frequency_khz < kAdfBandLowKhz || frequency_khz > kAdfBandHighKhz) {
    best.status = radio::SignalStatus::kNotTuned;
    return best;
  }
  if (!radio::pose_problem(pose).empty()) {
    best.status = radio::SignalStatus::kInvalidInput;
    return best;
  }
  double best_distance_m = std::numeric_limits<double>::infinity();
  bool any = false;
  for (const Navaid& navaid : source_->stations_on(frequency_khz).navaids) {
    if (!radio::has_ndb(navaid)) continue;
    AdfReading candidate;
    const double bound_m = radio::ground_distance_lower_bound_m(navaid.position, pose.lat_rad, pose.lon_rad);
    if (bound_m > radio::kReceptionLimitM) {  // beyond any reception: flagged, no geometry computed
      candidate.ident = navaid.ident;
      candidate.status = radio::SignalStatus::kOutOfServiceVolume;
      if (!any || (!best.valid() && bound_m < best_distance_m)) {
        best = candidate;
        best_distance_m = bound_m;
        any = true;
      }
      continue;
    }
    if (outages_->off_air(navaid.ident)) {
      radio::check_navaid(navaid);
      candidate.ident = navaid.ident;
      candidate.status = radio::SignalStatus::kStationOffAir;
    } else {
      candidate = adf_.read(navaid, pose);
    }
    const double distance_m = radio::ground_distance_m(navaid.position, pose.lat_rad, pose.lon_rad);
    const bool better = !any || (candidate.valid() && !best.valid()) ||
                        (candidate.valid() == best.valid() && distance_m < best_distance_m);
    if (better) {
      best = candidate;
      best_distance_m = distance_m;
      any = true;
    }
  }
  return best;
}

}  // namespace fedsim::nav
