// Service volumes of the radio navigation aids: how far a station is usable, by its class.
//
// Source: FAA Aeronautical Information Manual 1-1-8, Table 1-1-1 "VOR/DME/TACAN Standard Service
// Volumes" and Table 1-1-2 "NDB Service Volumes":
//   T (terminal)  up to 12,000 ft above the station: 25 NM
//   L (low)       up to 18,000 ft: 40 NM
//   H (high)      up to 14,500 ft: 40 NM; 14,500-60,000 ft: 100 NM; 18,000-45,000 ft: 130 NM
//   NDB: compass locator (< 25 W) 15 NM, MH (< 50 W) 25 NM, H (50-1999 W) 50 NM,
//        HH (>= 2000 W) 75 NM, the same at all altitudes.
// The standard volumes start 1,000 ft above the station; below that this model does not cut the
// signal off (reception near the ground is governed by the radio horizon, radio_geometry.hpp).
//
// OurAirports (navaids.csv, from DAFIF) gives a usage type and a power class rather than the FAA
// class; the mapping used:
//   VHF: usage TERMINAL -> T, LO -> L, HI or BOTH -> H (a station serving the high structure needs
//        the high volume); otherwise by power HIGH -> H, MEDIUM -> L, LOW -> T, unknown -> L.
//   NDB: power LOW with usage TERMINAL (a locator) or UNKNOWN with TERMINAL -> compass locator;
//        LOW -> MH; MEDIUM -> H; HIGH -> HH; unknown -> MH (DAFIF's power bands match the
//        AIM's wattages: L < 50 W, M 50-1999 W, H >= 2000 W).
#pragma once

#include "common/navdb/nav_records.hpp"
#include "common/radio/radio_geometry.hpp"
#include "common/radio/signal_status.hpp"

#include <cstdint>

namespace fedsim::radio {

enum class VhfServiceClass : std::uint8_t { kTerminal, kLow, kHigh };
enum class NdbServiceClass : std::uint8_t { kCompassLocator, kMediumHigh, kHigh, kHighHigh };

VhfServiceClass vhf_service_class(const nav::Navaid& navaid);
NdbServiceClass ndb_service_class(const nav::Navaid& navaid);

/// Radial distance [m] to which the standard service volume of `service_class` reaches at a
/// height above the station [m]; 0 above the volume's top (60,000 ft for H).
double vhf_service_range_m(VhfServiceClass service_class, double height_above_station_m);
/// Radius [m] of an NDB's service volume (all altitudes).
double ndb_service_range_m(NdbServiceClass service_class);

/// Whether a VHF/UHF station of `service_class` reaches the aircraft over `link`: kValid inside
/// the radio line of sight and the service volume, else kBelowRadioHorizon (checked first: the
/// path is physically blocked) or kOutOfServiceVolume. Heights are above MSL [m].
SignalStatus vhf_reception(VhfServiceClass service_class, const LinkGeometry& link,
                           double station_msl_m, double aircraft_msl_m);

}  // namespace fedsim::radio
