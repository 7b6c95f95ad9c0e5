#include "common/radio/receiver_link.hpp"

namespace fedsim::radio {

ReceiverLink receiver_link(const nav::GeoPoint& antenna, const AircraftPose& pose) {
  if (!pose_problem(pose).empty()) return ReceiverLink{SignalStatus::kInvalidInput, {}};
  return ReceiverLink{SignalStatus::kValid,
                      link_geometry(antenna, pose.lat_rad, pose.lon_rad, pose.altitude_msl_m)};
}

ReceiverLink vhf_receiver_link(const nav::GeoPoint& antenna, VhfServiceClass service_class,
                               const AircraftPose& pose) {
  ReceiverLink path = receiver_link(antenna, pose);
  if (path.status == SignalStatus::kValid) {
    path.status = vhf_reception(service_class, path.link, antenna.elevation_m, pose.altitude_msl_m);
  }
  return path;
}

IlsReception ils_reception(const nav::IlsApproach& approach, const nav::GeoPoint& antenna,
                           const AircraftPose& pose) {
  IlsReception reception{approach_geometry(approach), receiver_link(antenna, pose)};
  ReceiverLink& path = reception.path;
  if (path.status == SignalStatus::kValid &&
      !within_radio_line_of_sight(antenna.elevation_m, pose.altitude_msl_m,
                                  path.link.ground_distance_m)) {
    path.status = SignalStatus::kBelowRadioHorizon;
  }
  return reception;
}

}  // namespace fedsim::radio
