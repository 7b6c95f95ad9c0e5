// A StationSource over records held in memory (tests, scenarios, a small cache). add() checks
// the record (std::invalid_argument naming the station and field). Adding a record invalidates
// the spans previously returned for its frequency.
#pragma once

#include "common/radio/station_source.hpp"

#include <map>
#include <vector>

namespace fedsim::radio {

class InMemoryStationSource final : public StationSource {
 public:
  void add(nav::Navaid navaid);
  void add(nav::IlsApproach approach);
  StationsOnFrequency stations_on(std::uint32_t frequency_khz) const override;

 private:
  std::map<std::uint32_t, std::vector<nav::Navaid>> navaids_;
  std::map<std::uint32_t, std::vector<nav::IlsApproach>> approaches_;
};

}  // namespace fedsim::radio
