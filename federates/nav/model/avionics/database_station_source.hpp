// The radios' StationSource on the navigation database (common/navdb): the stations on a
// frequency are read from SQLite once, on first use, and kept (a frequency's stations do not
// change during a run), so the per-frame look-up is a map find with no query and no allocation.
// The ILS approaches are all read at construction: the marker receiver hears every marker
// beacon near the aircraft, whatever the NAV radios are tuned to.
#pragma once

#include "common/navdb/nav_database.hpp"
#include "common/radio/station_source.hpp"

#include <cstdint>
#include <map>
#include <span>
#include <vector>

namespace fedsim::nav {

class DatabaseStationSource final : public radio::StationSource {
 public:
  /// Holds `database` by reference: it must outlive the source.
  explicit DatabaseStationSource(const NavDatabase& database);

  radio::StationsOnFrequency stations_on(std::uint32_t frequency_khz) const override;
  /// Every ILS approach of the database.
  std::span<const IlsApproach> all_approaches() const { return approaches_; }
  /// Frequencies read from the database so far.
  std::size_t cached_frequencies() const { return cache_.size(); }

 private:
  struct OnFrequency {
    std::vector<Navaid> navaids;
    std::vector<IlsApproach> approaches;
  };
  const NavDatabase* database_;
  std::vector<IlsApproach> approaches_;
  mutable std::map<std::uint32_t, OnFrequency> cache_;
};

}  // namespace fedsim::nav
