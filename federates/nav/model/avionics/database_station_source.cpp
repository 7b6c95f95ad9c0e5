#include "nav/model/avionics/database_station_source.hpp"

#include "common/radio/nav_radio.hpp"

namespace fedsim::nav {

namespace {
// ILS localizers use 108.10-111.95 MHz at odd tenths (ICAO Annex 10 Vol I 3.1.3.2.1): every
// 50 kHz channel of that span is asked once.
constexpr std::uint32_t kLocalizerLowKhz = 108100;
constexpr std::uint32_t kLocalizerHighKhz = 111950;
constexpr std::uint32_t kChannelSpacingKhz = 50;
}  // namespace

DatabaseStationSource::DatabaseStationSource(const NavDatabase& database) : database_(&database) {
  for (std::uint32_t khz = kLocalizerLowKhz; khz <= kLocalizerHighKhz; khz += kChannelSpacingKhz) {
    for (IlsApproach& ils : database.ils_on_frequency(khz)) approaches_.push_back(std::move(ils));
  }
}

radio::StationsOnFrequency DatabaseStationSource::stations_on(std::uint32_t frequency_khz) const {
  auto it = cache_.find(frequency_khz);
  if (it == cache_.end()) {
    OnFrequency entry;
    entry.navaids = database_->on_frequency(frequency_khz);
    if (frequency_khz >= radio::kNavBandLowKhz && frequency_khz <= radio::kNavBandHighKhz) {
      entry.approaches = database_->ils_on_frequency(frequency_khz);
    }
    it = cache_.emplace(frequency_khz, std::move(entry)).first;
  }
  return {it->second.navaids, it->second.approaches};
}

}  // namespace fedsim::nav
