#include "nav/model/radio/adf_receiver.hpp"

#include "common/radio/radio_geometry.hpp"
#include "common/radio/receiver_link.hpp"
#include "common/radio/service_volume.hpp"
#include "common/radio/station_checks.hpp"

#include <stdexcept>

namespace fedsim::nav {

AdfReading AdfReceiver::read(const Navaid& ndb, const radio::AircraftPose& pose) const {
  radio::check_navaid(ndb);
  if (!radio::has_ndb(ndb)) {
    throw std::invalid_argument("AdfReceiver: navaid '" + ndb.ident + "' is not an NDB");
  }
  const radio::ReceiverLink path = radio::receiver_link(ndb.position, pose);
  AdfReading reading{.status = path.status, .ident = ndb.ident};
  if (!reading.valid()) return reading;
  const radio::LinkGeometry& link = path.link;
  if (link.ground_distance_m > radio::ndb_service_range_m(radio::ndb_service_class(ndb))) {
    reading.status = radio::SignalStatus::kOutOfServiceVolume;
    return reading;
  }
  reading.bearing_to_station_true_rad = link.azimuth_to_station_true_rad;
  reading.relative_bearing_rad =
      radio::wrap_two_pi(link.azimuth_to_station_true_rad - pose.heading_true_rad);
  reading.ground_distance_m = link.ground_distance_m;
  return reading;
}

}  // namespace fedsim::nav
