#include "nav/model/radio/adf_receiver.hpp"

#include "nav/model/radio/radio_geometry.hpp"
#include "nav/model/radio/receiver_link.hpp"
#include "nav/model/radio/service_volume.hpp"
#include "nav/model/radio/station_checks.hpp"

#include <stdexcept>

namespace fedsim::nav {

AdfReading AdfReceiver::read(const Navaid& ndb, const AircraftPose& pose) const {
  check_navaid(ndb);
  if (!has_ndb(ndb)) {
    throw std::invalid_argument("AdfReceiver: navaid '" + ndb.ident + "' is not an NDB");
  }
  const ReceiverLink path = receiver_link(ndb.position, pose);
  AdfReading reading{.status = path.status, .ident = ndb.ident};
  if (!reading.valid()) return reading;
  const LinkGeometry& link = path.link;
  if (link.ground_distance_m > ndb_service_range_m(ndb_service_class(ndb))) {
    reading.status = SignalStatus::kOutOfServiceVolume;
    return reading;
  }
  reading.bearing_to_station_true_rad = link.azimuth_to_station_true_rad;
  reading.relative_bearing_rad =
      wrap_two_pi(link.azimuth_to_station_true_rad - pose.heading_true_rad);
  reading.ground_distance_m = link.ground_distance_m;
  return reading;
}

}  // namespace fedsim::nav
