// Ground stations off the air (instructor failures, NOTAMs): by ident, the whole station or one
// component of it (the DME of a VOR-DME, the glide slope or the markers of an ILS). The radios
// consult it every frame: a station off the air gives status kStationOffAir, and a co-channel
// station that is on the air may then be received instead.
// Idents are not unique world-wide (OurAirports has "SAU" in France and in the US): taking an
// ident off the air takes off every station that carries it.
#pragma once

#include <cstdint>
#include <functional>
#include <map>
#include <string>
#include <string_view>

namespace fedsim::radio {

enum class StationComponent : std::uint8_t {
  kAll,         // the whole station
  kDme,         // the DME of a VOR-DME / VORTAC / ILS-DME
  kGlideSlope,  // the glide slope of an ILS (the localizer stays)
  kMarkers,     // the marker beacons of an ILS
};

class StationOutages {
 public:
  /// Takes `component` of the station `ident` off the air (off_air = true) or back on.
  /// Throws std::invalid_argument for an empty ident.
  void set_off_air(std::string_view ident, StationComponent component = StationComponent::kAll,
                   bool off_air = true);
  /// True when the station, or the given component of it, is off the air. No allocation.
  bool off_air(std::string_view ident, StationComponent component = StationComponent::kAll) const;
  void clear() { components_.clear(); }
  bool empty() const { return components_.empty(); }

 private:
  static std::uint8_t bit(StationComponent component);
  std::map<std::string, std::uint8_t, std::less<>> components_;  // ident -> component bits
};

}  // namespace fedsim::radio
