#include "common/radio/nav_radio.hpp"

#include "common/radio/radio_geometry.hpp"
#include "common/radio/station_checks.hpp"

#include <cmath>
#include <limits>
#include <utility>

namespace fedsim::radio {

namespace {

// The candidate to keep: a valid reading before an invalid one, then the nearer.
template <class Reading>
struct Nearest {
  Reading reading;
  double distance_m = std::numeric_limits<double>::infinity();
  bool any = false;

  bool offer(Reading candidate, double candidate_distance_m) {
    const bool better = !any || (candidate.valid() && !reading.valid()) ||
                        (candidate.valid() == reading.valid() && candidate_distance_m < distance_m);
    if (!better) return false;
    reading = std::move(candidate);
    distance_m = candidate_distance_m;
    any = true;
    return true;
  }
};

template <class Reading>
Reading reading_with(const std::string& ident, SignalStatus status) {
  Reading reading;
  reading.ident = ident;
  reading.status = status;
  return reading;
}

template <class Reading>
Reading off_air_reading(const std::string& ident) {
  return reading_with<Reading>(ident, SignalStatus::kStationOffAir);
}

/// A station beyond any reception (radio_geometry.hpp): flagged without its geometry.
template <class Reading>
Reading far_reading(const std::string& ident) {
  return reading_with<Reading>(ident, SignalStatus::kOutOfServiceVolume);
}

void set_every_status(NavReading& reading, SignalStatus status) {
  reading.status = status;
  reading.vor.status = status;
  reading.localizer.status = status;
  reading.glide_slope.status = status;
  reading.dme.status = status;
}

}  // namespace

std::string_view NavReading::ident() const {
  switch (signal) {
    case NavSignal::kVor: return vor.ident;
    case NavSignal::kLocalizer: return localizer.ident;
    case NavSignal::kNone: break;
  }
  return {};
}

double NavReading::course_deviation() const {
  if (!valid()) return 0.0;
  return signal == NavSignal::kVor ? vor.course_deviation : localizer.deviation;
}

double NavReading::course_true_rad() const {
  if (!valid()) return 0.0;
  return signal == NavSignal::kVor ? vor.course_true_rad : localizer.course_true_rad;
}

double NavReading::bearing_to_station_true_rad() const {
  if (!valid()) return 0.0;
  return signal == NavSignal::kVor ? vor.bearing_to_station_true_rad
                                   : localizer.bearing_to_antenna_true_rad;
}

NavRadio::NavRadio(const StationSource& source, const StationOutages& outages,
                   VorReceiverSettings vor_settings)
    : source_(&source), outages_(&outages), vor_(vor_settings) {}

NavReading NavRadio::receive(const NavTuning& tuning, const AircraftPose& pose) const {
  NavReading reading;
  if (failed_) {
    set_every_status(reading, SignalStatus::kReceiverFailed);
    return reading;
  }
  if (tuning.frequency_khz < kNavBandLowKhz || tuning.frequency_khz > kNavBandHighKhz) {
    set_every_status(reading, SignalStatus::kNotTuned);
    return reading;
  }
  if (!pose_problem(pose).empty() || !std::isfinite(tuning.obs_course_magnetic_rad)) {
    set_every_status(reading, SignalStatus::kInvalidInput);
    return reading;
  }
  const StationsOnFrequency stations = source_->stations_on(tuning.frequency_khz);
  receive_course(stations, tuning, pose, reading);
  receive_glide_slope(pose, reading);
  reading.dme = receive_dme(stations, pose);
  return reading;
}

void NavRadio::receive_course(const StationsOnFrequency& stations, const NavTuning& tuning,
                              const AircraftPose& pose, NavReading& reading) const {
  Nearest<VorReading> vor;
  for (const nav::Navaid& navaid : stations.navaids) {
    if (!has_vor(navaid)) continue;
    const double bound_m = ground_distance_lower_bound_m(navaid.position, pose.lat_rad, pose.lon_rad);
    if (bound_m > kReceptionLimitM) {
      vor.offer(far_reading<VorReading>(navaid.ident), bound_m);
      continue;
    }
    const double distance_m = ground_distance_m(navaid.position, pose.lat_rad, pose.lon_rad);
    if (outages_->off_air(navaid.ident)) {
      check_navaid(navaid);
      vor.offer(off_air_reading<VorReading>(navaid.ident), distance_m);
    } else {
      vor.offer(vor_.read(navaid, pose, tuning.obs_course_magnetic_rad), distance_m);
    }
  }
  Nearest<LocalizerReading> localizer;
  const nav::IlsApproach* localizer_approach = nullptr;
  for (const nav::IlsApproach& approach : stations.approaches) {
    const double bound_m =
        ground_distance_lower_bound_m(approach.localizer, pose.lat_rad, pose.lon_rad);
    if (bound_m > kReceptionLimitM) {
      if (localizer.offer(far_reading<LocalizerReading>(approach.ident), bound_m)) {
        localizer_approach = &approach;
      }
      continue;
    }
    const double distance_m =
        ground_distance_m(approach.localizer, pose.lat_rad, pose.lon_rad);
    LocalizerReading candidate;
    if (outages_->off_air(approach.ident)) {
      check_approach(approach);
      candidate = off_air_reading<LocalizerReading>(approach.ident);
    } else {
      candidate = localizer_.read(approach, pose);
    }
    if (localizer.offer(std::move(candidate), distance_m)) localizer_approach = &approach;
  }
  if (!vor.any && !localizer.any) {
    reading.status = SignalStatus::kNoStation;
    return;
  }
  const bool take_localizer =
      localizer.any &&
      (!vor.any || (localizer.reading.valid() && !vor.reading.valid()) ||
       (localizer.reading.valid() == vor.reading.valid() && localizer.distance_m < vor.distance_m));
  if (take_localizer) {
    reading.signal = NavSignal::kLocalizer;
    reading.localizer = std::move(localizer.reading);
    reading.status = reading.localizer.status;
    reading.approach = localizer_approach;
  } else {
    reading.signal = NavSignal::kVor;
    reading.vor = std::move(vor.reading);
    reading.status = reading.vor.status;
  }
}

void NavRadio::receive_glide_slope(const AircraftPose& pose, NavReading& reading) const {
  if (reading.approach == nullptr) return;  // stays kNoStation
  const nav::IlsApproach& approach = *reading.approach;
  if (outages_->off_air(approach.ident, StationComponent::kGlideSlope)) {
    reading.glide_slope = off_air_reading<GlideSlopeReading>(approach.ident);
    return;
  }
  reading.glide_slope = glide_slope_.read(approach, pose);
}

DmeReading NavRadio::receive_dme(const StationsOnFrequency& stations,
                                 const AircraftPose& pose) const {
  Nearest<DmeReading> nearest;
  const auto offer = [&](const std::optional<DmeStation>& station) {
    if (!station) return;
    const double bound_m =
        ground_distance_lower_bound_m(station->antenna, pose.lat_rad, pose.lon_rad);
    if (bound_m > kReceptionLimitM) {
      nearest.offer(far_reading<DmeReading>(station->ident), bound_m);
      return;
    }
    const double distance_m =
        ground_distance_m(station->antenna, pose.lat_rad, pose.lon_rad);
    if (outages_->off_air(station->ident, StationComponent::kDme)) {
      nearest.offer(off_air_reading<DmeReading>(station->ident), distance_m);
    } else {
      nearest.offer(dme_.read(*station, pose), distance_m);
    }
  };
  for (const nav::Navaid& navaid : stations.navaids) offer(dme_station(navaid));
  for (const nav::IlsApproach& approach : stations.approaches) offer(dme_station(approach));
  return nearest.any ? nearest.reading : DmeReading{};
}

}  // namespace fedsim::radio
