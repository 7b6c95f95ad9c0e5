// Where the radios find the stations on a frequency. The federate's adapter implements it on
// the navigation database (common/navdb) with a cache; InMemoryStationSource serves tests and
// scenarios with a handful of records.
#pragma once

#include "common/navdb/nav_records.hpp"

#include <cstdint>
#include <span>

namespace fedsim::radio {

/// Every record on one frequency. The spans refer to storage owned by the source and must stay
/// valid, unchanged, until the source is modified or destroyed (a std::map of vectors per
/// frequency filled on first use satisfies this): a NavReading points into it.
struct StationsOnFrequency {
  std::span<const nav::Navaid> navaids;          // VOR, DME, TACAN (paired VHF), NDB on this frequency
  std::span<const nav::IlsApproach> approaches;  // ILS localizers on this frequency
};

class StationSource {
 public:
  virtual ~StationSource() = default;
  /// The stations on `frequency_khz` (VOR/ILS 108000-117950, NDB 190-1750). Called for every
  /// radio every frame: an implementation should not query a database each time.
  virtual StationsOnFrequency stations_on(std::uint32_t frequency_khz) const = 0;
};

}  // namespace fedsim::radio
