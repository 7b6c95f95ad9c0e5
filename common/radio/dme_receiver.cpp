#include "common/radio/dme_receiver.hpp"

#include "common/radio/radio_geometry.hpp"
#include "common/radio/receiver_link.hpp"
#include "common/radio/station_checks.hpp"
#include "common/units/units.hpp"

#include <cmath>
#include <stdexcept>

namespace fedsim::radio {

namespace {

bool has_vhf_paired_dme(nav::NavaidType type) {
  return type == nav::NavaidType::kVorDme || type == nav::NavaidType::kVortac || type == nav::NavaidType::kDme ||
         type == nav::NavaidType::kTacan;
}

void check_antenna(const DmeStation& station) {
  const nav::GeoPoint& a = station.antenna;
  if (!std::isfinite(a.lat_rad) || std::abs(a.lat_rad) > units::kHalfPi ||
      !std::isfinite(a.lon_rad) || std::abs(a.lon_rad) > units::kPi ||
      !std::isfinite(a.elevation_m) || std::abs(a.elevation_m) > 9000.0) {
    throw std::invalid_argument("DME '" + station.ident + "': antenna position out of range");
  }
}

}  // namespace

std::optional<DmeStation> dme_station(const nav::Navaid& navaid) {
  check_navaid(navaid);
  if (!has_vhf_paired_dme(navaid.type)) return std::nullopt;
  return DmeStation{navaid.ident, navaid.dme.value_or(navaid.position),
                    vhf_service_class(navaid)};
}

std::optional<DmeStation> dme_station(const nav::IlsApproach& approach) {
  check_approach(approach);
  if (!approach.has_dme) return std::nullopt;
  return DmeStation{approach.ident, approach.glide_slope, VhfServiceClass::kTerminal};
}

DmeReading DmeReceiver::read(const DmeStation& station, const AircraftPose& pose) const {
  check_antenna(station);
  const ReceiverLink path = vhf_receiver_link(station.antenna, station.service_class, pose);
  DmeReading reading{.status = path.status, .ident = station.ident};
  if (!reading.valid()) return reading;
  reading.slant_range_m = path.link.slant_range_m;
  reading.ground_distance_m = path.link.ground_distance_m;
  return reading;
}

}  // namespace fedsim::radio
