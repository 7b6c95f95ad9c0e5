// VOR receiver and course deviation indicator (seed 6.6).
//
// Inputs: the station record (Navaid with a VOR: VOR, VOR-DME, VORTAC), the aircraft pose
// (AircraftPose: position, altitude MSL) and the OBS course (magnetic [rad]).
// Outputs (VorReading):
//   radial: the magnetic azimuth of the aircraft seen from the station, i.e. the geodesic azimuth
//     at the station (not the reciprocal of the bearing at the aircraft: the two differ by the
//     convergence of the meridians) minus the variation the VOR is aligned to (its slaved
//     variation when known, else the magnetic variation at the site; east positive);
//   TO/FROM: FROM when the radial is within 90 deg of the OBS course, TO beyond, OFF within
//     `to_from_band_rad` of 90 deg (the selected course neither leads to nor from the station);
//   course deviation: the angle between the radial and the selected course line, + = fly right
//     (the course line is to the right of an aircraft flying the OBS course), full scale
//     +-10 deg (five dots of 2 deg; the FAA Instrument Flying Handbook, FAA-H-8083-15,
//     "Navigation Systems", gives 10-12 deg by indicator), output clamped to -1..1 ("+ = fly
//     right" as in idl/navigation.idl NavReceiver).
//     FROM: fly_right = OBS - radial; TO: fly_right = radial + 180 deg - OBS (both wrapped), so
//     the needle keeps its sense across the station;
//   valid only inside the service volume and the radio line of sight (service_volume.hpp) and
//     outside the cone of confusion: no usable bearing more than 60 deg above the station's
//     horizontal (ICAO Annex 10 Vol I 3.3.3.1 requires signals up to 40 deg elevation; the
//     conventional VOR's pattern is taken as usable to 60 deg, the "cone of airspace directly above
//     the facility" of AIM FIG 1-1-2 has a 30 deg half-angle about the vertical).
// Per-frame inputs are not thrown on: a bad pose or OBS gives status kInvalidInput. A bad record
// or a record without a VOR throws std::invalid_argument. Errors of a real VOR (site errors,
// scalloping) are not modelled: the bearing is exact.
#pragma once

#include "common/navdb/nav_records.hpp"
#include "common/radio/aircraft_pose.hpp"
#include "common/radio/signal_status.hpp"
#include "common/units/units.hpp"

#include <cstdint>
#include <string>

namespace fedsim::radio {

enum class ToFrom : std::uint8_t { kOff, kTo, kFrom };

struct VorReceiverSettings {
  double full_scale_rad = 10.0 * units::kDegToRad;              // CDI full-scale deflection
  double to_from_band_rad = 2.0 * units::kDegToRad;             // OFF half-band about +-90 deg
  double cone_of_confusion_elevation_rad = 60.0 * units::kDegToRad;  // no bearing above this
};

struct VorReading {
  SignalStatus status = SignalStatus::kNoStation;
  std::string ident;                         // the station's ident (also when not valid)
  double radial_magnetic_rad = 0.0;          // radial the aircraft is on, [0, 2 pi)
  double bearing_to_station_true_rad = 0.0;  // at the aircraft, [0, 2 pi)
  double bearing_to_station_magnetic_rad = 0.0;  // [0, 2 pi)
  double variation_rad = 0.0;                // the VOR's alignment variation, east + [rad]
  double course_true_rad = 0.0;              // the OBS course converted with that variation
  double course_error_rad = 0.0;             // angle off the course line, + = fly right
  double course_deviation = 0.0;             // CDI, -1..1 full scale, + = fly right [-]
  ToFrom to_from = ToFrom::kOff;
  double ground_distance_m = 0.0;            // geodesic distance to the station [m]
  double slant_range_m = 0.0;                // straight-line distance to the antenna [m]
  double elevation_angle_rad = 0.0;          // of the aircraft above the station [rad]
  bool valid() const { return status == SignalStatus::kValid; }
};

class VorReceiver {
 public:
  /// Throws std::invalid_argument unless 0 < full scale < 90 deg, 0 <= band < 45 deg and
  /// 0 < cone elevation <= 90 deg.
  explicit VorReceiver(VorReceiverSettings settings = {});

  VorReading read(const nav::Navaid& vor, const AircraftPose& pose,
                  double obs_course_magnetic_rad) const;

  const VorReceiverSettings& settings() const { return settings_; }

 private:
  void fill_course(double obs_course_magnetic_rad, VorReading& reading) const;

  VorReceiverSettings settings_;
};

}  // namespace fedsim::radio
