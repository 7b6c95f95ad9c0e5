#include "common/radio/in_memory_station_source.hpp"

#include "common/radio/station_checks.hpp"

#include <utility>

namespace fedsim::radio {

void InMemoryStationSource::add(nav::Navaid navaid) {
  check_navaid(navaid);
  const std::uint32_t khz = navaid.frequency_khz;
  navaids_[khz].push_back(std::move(navaid));
}

void InMemoryStationSource::add(nav::IlsApproach approach) {
  check_approach(approach);
  const std::uint32_t khz = approach.frequency_khz;
  approaches_[khz].push_back(std::move(approach));
}

StationsOnFrequency InMemoryStationSource::stations_on(std::uint32_t frequency_khz) const {
  StationsOnFrequency stations;
  if (const auto it = navaids_.find(frequency_khz); it != navaids_.end()) {
    stations.navaids = it->second;
  }
  if (const auto it = approaches_.find(frequency_khz); it != approaches_.end()) {
    stations.approaches = it->second;
  }
  return stations;
}

}  // namespace fedsim::radio
