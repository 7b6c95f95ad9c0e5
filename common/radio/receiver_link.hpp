// The checks every single-station receiver (VOR, DME, ADF, ILS localizer and glide slope) makes
// before its own, in one place and one order:
//   1. the pose: a per-frame sample outside its ranges gives kInvalidInput (the receivers flag
//      a bad sample rather than throw, aircraft_pose.hpp);
//   2. the path from the station's antenna to the aircraft (link_geometry, radio_geometry.hpp);
//   3. what the kind of station needs next: the VHF/UHF line of sight and service volume of a
//      VOR or DME (vhf_reception, service_volume.hpp), or the line of sight alone for the ILS
//      (kBelowRadioHorizon; the receivers then test their own coverage sectors).
// A status other than kValid stops the reading: the receiver returns it with its numerical
// fields zero. Bad station records throw std::invalid_argument (station_checks.hpp,
// approach_geometry.hpp).
#pragma once

#include "common/navdb/nav_records.hpp"
#include "common/radio/aircraft_pose.hpp"
#include "common/radio/approach_geometry.hpp"
#include "common/radio/radio_geometry.hpp"
#include "common/radio/service_volume.hpp"
#include "common/radio/signal_status.hpp"

namespace fedsim::radio {

struct ReceiverLink {
  SignalStatus status = SignalStatus::kValid;  // kValid: the reading goes on
  LinkGeometry link;                           // antenna -> aircraft (computed for a good pose)
};

/// Steps 1 and 2: the pose and the path to `antenna` (the ADF, whose NDB range it tests itself).
ReceiverLink receiver_link(const nav::GeoPoint& antenna, const AircraftPose& pose);

/// Steps 1 to 3 for a VOR or DME antenna of `service_class`.
ReceiverLink vhf_receiver_link(const nav::GeoPoint& antenna, VhfServiceClass service_class,
                               const AircraftPose& pose);

/// What an ILS receiver starts from: the approach's geometry (its record checked: throws), and
/// steps 1 to 3 to one of its antennas (localizer or glide slope).
struct IlsReception {
  ApproachGeometry geometry;
  ReceiverLink path;
};
IlsReception ils_reception(const nav::IlsApproach& approach, const nav::GeoPoint& antenna,
                           const AircraftPose& pose);

}  // namespace fedsim::radio
