// DME interrogator (seed 6.7): slant range to a DME ground antenna.
//
// Inputs: a DmeStation (the antenna position and its service class, made from a Navaid with a DME
// — VOR-DME, VORTAC, DME, TACAN — or from an ILS approach with a paired DME) and the aircraft
// pose. Outputs (DmeReading): the slant range [m] (straight line, ECEF: what the pulse timing
// measures, so it never falls below the height above the antenna) and the geodesic ground
// distance [m]; status kOutOfServiceVolume ("no computed data") beyond the standard service
// volume of the station's class (FAA AIM 1-1-8 Table 1-1-1 covers DME and TACAN: T 25 NM, L 40 NM,
// H up to 130 NM; an ILS DME is taken as T) and kBelowRadioHorizon beyond the UHF line of sight.
// DME has no cone of confusion: it reads the height overhead. Per-frame inputs: a bad pose gives
// kInvalidInput; a bad station throws std::invalid_argument.
#pragma once

#include "common/navdb/nav_records.hpp"
#include "common/radio/aircraft_pose.hpp"
#include "common/radio/service_volume.hpp"
#include "common/radio/signal_status.hpp"

#include <optional>
#include <string>

namespace fedsim::radio {

struct DmeStation {
  std::string ident;
  nav::GeoPoint antenna;  // the DME antenna (WGS-84 [rad], elevation MSL [m])
  VhfServiceClass service_class = VhfServiceClass::kLow;
};

/// The DME of a VOR-DME, VORTAC, DME or TACAN (at `dme` when the record gives a separate antenna,
/// else at `position`); nullopt for stations without one (VOR, NDB; an NDB-DME's DME is not
/// paired with a VHF frequency the NAV receiver tunes). Throws on a bad record.
std::optional<DmeStation> dme_station(const nav::Navaid& navaid);
/// The DME paired with an ILS localizer (has_dme), at the glide-slope antenna as the record
/// states, service class terminal; nullopt without one. Throws on a bad record.
std::optional<DmeStation> dme_station(const nav::IlsApproach& approach);

struct DmeReading {
  SignalStatus status = SignalStatus::kNoStation;
  std::string ident;
  double slant_range_m = 0.0;      // [m]
  double ground_distance_m = 0.0;  // [m]
  bool valid() const { return status == SignalStatus::kValid; }
};

class DmeReceiver {
 public:
  DmeReading read(const DmeStation& station, const AircraftPose& pose) const;
};

}  // namespace fedsim::radio
