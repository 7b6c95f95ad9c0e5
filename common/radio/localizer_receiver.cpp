#include "common/radio/localizer_receiver.hpp"

#include "common/radio/approach_geometry.hpp"
#include "common/radio/radio_geometry.hpp"
#include "common/radio/receiver_link.hpp"
#include "common/units/units.hpp"

#include <algorithm>
#include <cmath>

namespace fedsim::radio {

namespace {

constexpr double kInnerSectorRad = 10.0 * units::kDegToRad;
constexpr double kInnerRangeM = 18.0 * units::kNmToM;
constexpr double kOuterSectorRad = 35.0 * units::kDegToRad;
constexpr double kOuterRangeM = 10.0 * units::kNmToM;
constexpr double kCeilingAboveAntennaM = 4500.0 * units::kFtToM;   // FAA AIM 1-1-9 b
constexpr double kCeilingElevationRad = 7.0 * units::kDegToRad;    // ICAO Annex 10 3.1.3.3.2

SignalStatus coverage_status(const LinkGeometry& link, double angle_off_course_rad) {
  const double off = std::abs(angle_off_course_rad);
  if (off > units::kHalfPi) return SignalStatus::kBehindAntenna;
  const bool inner = off <= kInnerSectorRad && link.ground_distance_m <= kInnerRangeM;
  const bool outer = off <= kOuterSectorRad && link.ground_distance_m <= kOuterRangeM;
  if (!inner && !outer) return SignalStatus::kOutsideCoverage;
  const double ceiling_m = std::max(kCeilingAboveAntennaM,
                                    link.ground_distance_m * std::tan(kCeilingElevationRad));
  if (link.height_above_station_m > ceiling_m) return SignalStatus::kOutsideCoverage;
  return SignalStatus::kValid;
}

}  // namespace

LocalizerReading LocalizerReceiver::read(const nav::IlsApproach& approach,
                                         const AircraftPose& pose) const {
  const IlsReception reception = ils_reception(approach, approach.localizer, pose);
  const ApproachGeometry& geometry = reception.geometry;
  LocalizerReading reading{.status = reception.path.status, .ident = approach.ident};
  if (!reading.valid()) return reading;
  const LinkGeometry& link = reception.path.link;
  const double angle_rad =
      wrap_pi(link.azimuth_from_station_true_rad - geometry.localizer_back_azimuth_rad);
  reading.status = coverage_status(link, angle_rad);
  if (!reading.valid()) return reading;
  reading.angle_off_course_rad = angle_rad;
  reading.ddm = kLocalizerFullScaleDdm * angle_rad / geometry.course_half_width_rad;
  reading.deviation = std::clamp(reading.ddm / kLocalizerFullScaleDdm, -1.0, 1.0);
  reading.course_true_rad = geometry.inbound_course_true_rad;
  reading.course_half_width_rad = geometry.course_half_width_rad;
  reading.bearing_to_antenna_true_rad = link.azimuth_to_station_true_rad;
  reading.distance_from_antenna_m = link.ground_distance_m;
  return reading;
}

}  // namespace fedsim::radio
