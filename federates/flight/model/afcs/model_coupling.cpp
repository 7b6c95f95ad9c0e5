#include "flight/model/afcs/model_coupling.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

namespace fedsim::flight::afcs {

GearGeometry GearGeometry::of(const AircraftPack& pack) {
  GearGeometry g;
  const double cg_x = pack.mass.empty_cg_m.x();
  const auto& contacts = pack.landing_gear.contacts;
  for (std::size_t i = 0; i < contacts.size(); ++i) {
    if (contacts[i].type != ContactType::wheel) continue;
    (contacts[i].position_m.x() < cg_x ? g.main_contacts : g.nose_contacts).push_back(i);
  }
  if (g.main_contacts.empty()) {
    throw std::invalid_argument("aircraft pack '" + pack.metadata.name +
                                "': no wheel aft of the CG (the AFCS needs the main gear)");
  }
  return g;
}

double main_gear_height_m(const AircraftOutputs& o, const AircraftPack& pack, const GearGeometry& gear) {
  double lowest = std::numeric_limits<double>::infinity();
  for (std::size_t i : gear.main_contacts) {
    const Eigen::Vector3d arm = pack.landing_gear.contacts[i].position_m - o.cg_m;
    const double below_cg_m = (o.ned_from_body * arm).z();
    lowest = std::min(lowest, o.height_agl_m - below_cg_m);
  }
  return lowest;
}

namespace {
bool any_on_ground(const AircraftOutputs& o, const std::vector<std::size_t>& contacts) {
  return std::any_of(contacts.begin(), contacts.end(), [&](std::size_t i) {
    return i < o.contacts.size() && o.contacts[i].weight_on_wheels;
  });
}
}  // namespace

AfcsAircraftState afcs_aircraft_state(const AircraftOutputs& o, const AircraftPack& pack,
                                      const GearGeometry& gear, const AircraftControls& pilot) {
  AfcsAircraftState a;
  a.time_s = o.time_s;
  a.roll_rad = o.euler.phi_rad;
  a.pitch_rad = o.euler.theta_rad;
  a.heading_true_rad = o.euler.psi_rad;
  a.roll_rate_radps = o.omega_body_wrt_earth_radps.x();
  a.pitch_rate_radps = o.omega_body_wrt_earth_radps.y();
  a.yaw_rate_radps = o.omega_body_wrt_earth_radps.z();
  a.calibrated_airspeed_mps = o.cas_mps;
  a.true_airspeed_mps = o.tas_mps;
  const Eigen::Vector2d v_horizontal = o.velocity_ned_mps.head<2>();
  a.ground_speed_mps = v_horizontal.norm();
  a.track_true_rad = a.ground_speed_mps > 1.0 ? std::atan2(v_horizontal.y(), v_horizontal.x()) : a.heading_true_rad;
  a.altitude_m = o.geodetic.alt_m;
  a.vertical_speed_mps = o.climb_rate_mps;
  a.radio_height_m = main_gear_height_m(o, pack, gear);
  a.angle_of_attack_rad = o.alpha_rad;
  a.sideslip_rad = o.beta_rad;
  a.lateral_specific_force_mps2 = o.specific_force_cg_body_mps2.y();
  const Eigen::Vector3d accel_ned = o.ned_from_body * o.acceleration_body_mps2;
  a.longitudinal_acceleration_mps2 =
      a.ground_speed_mps > 0.1 ? accel_ned.head<2>().dot(v_horizontal) / a.ground_speed_mps : 0.0;
  a.main_gear_on_ground = any_on_ground(o, gear.main_contacts);
  a.nose_gear_on_ground = any_on_ground(o, gear.nose_contacts);
  const AircraftControls c = pilot.clamped();
  a.elevator = c.elevator;
  a.aileron = c.aileron;
  a.rudder = c.rudder;
  a.throttle = c.throttle[0];
  a.pitch_trim = std::clamp(o.pitch_trim_norm, -1.0, 1.0);
  return a;
}

radio::AircraftPose nav_pose(const AircraftOutputs& o) {
  radio::AircraftPose pose;
  pose.lat_rad = o.geodetic.lat_rad;
  pose.lon_rad = o.geodetic.lon_rad;
  pose.altitude_msl_m = o.geodetic.alt_m;
  pose.heading_true_rad = o.euler.psi_rad;
  pose.pitch_rad = o.euler.theta_rad;
  pose.roll_rad = o.euler.phi_rad;
  pose.true_airspeed_mps = o.tas_mps;
  pose.climb_rate_mps = o.climb_rate_mps;
  return pose;
}

AfcsIlsSignals ils_signals(const radio::LocalizerReading& localizer, const radio::GlideSlopeReading& glide_slope,
                           const nav::IlsApproach& approach, const radio::ApproachGeometry& geometry,
                           const radio::AircraftPose& pose) {
  AfcsIlsSignals s;
  s.localizer_valid = localizer.valid();
  if (s.localizer_valid) {
    s.localizer_deviation = localizer.deviation;
    s.localizer_half_width_rad = localizer.course_half_width_rad;
    s.localizer_course_true_rad = localizer.course_true_rad;
    s.localizer_distance_m = localizer.distance_from_antenna_m;
  }
  s.glide_slope_valid = glide_slope.valid();
  if (s.glide_slope_valid) {
    s.glide_slope_deviation = glide_slope.deviation;
    s.glide_path_angle_rad = glide_slope.glide_path_angle_rad;
    s.glide_slope_distance_m = glide_slope.distance_from_antenna_m;
  }
  const radio::CourseCoordinates cc = radio::course_coordinates(approach, geometry, pose.lat_rad, pose.lon_rad);
  s.distance_to_threshold_m = cc.along_m - geometry.threshold_along_m;
  return s;
}

namespace {
VorToFrom to_from(radio::ToFrom flag) {
  switch (flag) {
    case radio::ToFrom::kTo: return VorToFrom::kTo;
    case radio::ToFrom::kFrom: return VorToFrom::kFrom;
    case radio::ToFrom::kOff: break;
  }
  return VorToFrom::kOff;
}
}  // namespace

AfcsVorSignals vor_signals(const radio::NavReading& nav, double full_scale_rad) {
  AfcsVorSignals v;
  v.tuned = nav.signal == radio::NavSignal::kVor;
  if (!v.tuned) return v;
  v.valid = nav.valid();
  v.cone_of_confusion = nav.status == radio::SignalStatus::kConeOfConfusion;
  if (v.valid) {
    v.deviation = nav.vor.course_deviation;
    v.full_scale_rad = full_scale_rad;
    v.course_true_rad = nav.vor.course_true_rad;
    v.to_from = to_from(nav.vor.to_from);
  }
  v.dme_valid = nav.dme.valid();
  if (v.dme_valid) v.dme_slant_range_m = nav.dme.slant_range_m;
  return v;
}

AfcsIlsSignals nav1_signals(const radio::NavReading& nav, const radio::AircraftPose& pose, double vor_full_scale_rad) {
  if (nav.signal == radio::NavSignal::kLocalizer && nav.approach != nullptr) {
    return ils_signals(nav.localizer, nav.glide_slope, *nav.approach, radio::approach_geometry(*nav.approach), pose);
  }
  AfcsIlsSignals s;
  s.vor = vor_signals(nav, vor_full_scale_rad);
  return s;
}

AircraftControls apply_afcs_outputs(const AfcsOutputs& afcs, const AircraftControls& pilot,
                                    double trim_position) {
  AircraftControls c = pilot;
  if (afcs.autopilot_engaged) {
    c.elevator = afcs.elevator;
    c.aileron = afcs.aileron;
    c.rudder = afcs.rudder;
    c.elevator_trim = afcs.pitch_trim_command == 0 ? trim_position
                                                   : static_cast<double>(afcs.pitch_trim_command);
  }
  if (afcs.autothrottle_engaged) c.set_throttle(afcs.throttle);
  if (afcs.rollout_engaged) {
    c.steering = afcs.steering;
    c.brake_left = afcs.brake_left;
    c.brake_right = afcs.brake_right;
    c.spoilers = afcs.spoilers;
  }
  return c;
}

}  // namespace fedsim::flight::afcs
