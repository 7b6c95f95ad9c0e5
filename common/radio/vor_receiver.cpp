#include "common/radio/vor_receiver.hpp"

#include "common/radio/radio_geometry.hpp"
#include "common/radio/receiver_link.hpp"
#include "common/radio/service_volume.hpp"
#include "common/radio/station_checks.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace fedsim::radio {

namespace {

void require(bool in_range, const char* name, double value) {
  if (!in_range || !std::isfinite(value)) {
    throw std::invalid_argument(std::string("VorReceiverSettings.") + name + " = " +
                                std::to_string(value) + " is out of range");
  }
}

}  // namespace

VorReceiver::VorReceiver(VorReceiverSettings settings) : settings_(settings) {
  const VorReceiverSettings& s = settings_;
  require(s.full_scale_rad > 0.0 && s.full_scale_rad < units::kHalfPi, "full_scale_rad",
          s.full_scale_rad);
  require(s.to_from_band_rad >= 0.0 && s.to_from_band_rad < 0.25 * units::kPi,
          "to_from_band_rad", s.to_from_band_rad);
  require(s.cone_of_confusion_elevation_rad > 0.0 &&
              s.cone_of_confusion_elevation_rad <= units::kHalfPi,
          "cone_of_confusion_elevation_rad", s.cone_of_confusion_elevation_rad);
}

VorReading VorReceiver::read(const nav::Navaid& vor, const AircraftPose& pose,
                             double obs_course_magnetic_rad) const {
  check_navaid(vor);
  if (!has_vor(vor)) {
    throw std::invalid_argument("VorReceiver: navaid '" + vor.ident + "' has no VOR");
  }
  // A non-finite OBS is a bad per-frame input like a bad pose.
  VorReading reading{.status = SignalStatus::kInvalidInput, .ident = vor.ident};
  if (!std::isfinite(obs_course_magnetic_rad)) return reading;
  const ReceiverLink path = vhf_receiver_link(vor.position, vhf_service_class(vor), pose);
  reading.status = path.status;
  if (!reading.valid()) return reading;
  const LinkGeometry& link = path.link;
  if (link.elevation_angle_rad > settings_.cone_of_confusion_elevation_rad) {
    reading.status = SignalStatus::kConeOfConfusion;
    return reading;
  }
  reading.variation_rad =
      vor.slaved_variation_known ? vor.slaved_variation_rad : vor.magnetic_variation_rad;
  reading.radial_magnetic_rad =
      wrap_two_pi(link.azimuth_from_station_true_rad - reading.variation_rad);
  reading.bearing_to_station_true_rad = link.azimuth_to_station_true_rad;
  reading.bearing_to_station_magnetic_rad =
      wrap_two_pi(link.azimuth_to_station_true_rad - reading.variation_rad);
  reading.ground_distance_m = link.ground_distance_m;
  reading.slant_range_m = link.slant_range_m;
  reading.elevation_angle_rad = link.elevation_angle_rad;
  fill_course(obs_course_magnetic_rad, reading);
  return reading;
}

void VorReceiver::fill_course(double obs_course_magnetic_rad, VorReading& reading) const {
  const double obs_rad = wrap_two_pi(obs_course_magnetic_rad);
  reading.course_true_rad = wrap_two_pi(obs_rad + reading.variation_rad);
  // Angle of the radial from the selected course: within 90 deg the course leads FROM the station.
  const double off_course_rad = wrap_pi(reading.radial_magnetic_rad - obs_rad);
  const double abs_off_rad = std::abs(off_course_rad);
  if (abs_off_rad < units::kHalfPi - settings_.to_from_band_rad) {
    reading.to_from = ToFrom::kFrom;
  } else if (abs_off_rad > units::kHalfPi + settings_.to_from_band_rad) {
    reading.to_from = ToFrom::kTo;
  } else {
    reading.to_from = ToFrom::kOff;
  }
  reading.course_error_rad = abs_off_rad <= units::kHalfPi
                                 ? -off_course_rad
                                 : wrap_pi(off_course_rad + units::kPi);
  reading.course_deviation =
      std::clamp(reading.course_error_rad / settings_.full_scale_rad, -1.0, 1.0);
}

}  // namespace fedsim::radio
