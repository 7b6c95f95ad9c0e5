#include "nav/model/avionics/avionics_suite.hpp"

#include "common/geodesy/wgs84.hpp"

#include <cmath>
#include <stdexcept>
#include <string>

namespace fedsim::nav {

namespace {
bool finite3(const Eigen::Vector3d& v) { return v.allFinite(); }
}  // namespace

std::string_view truth_problem(const AvionicsTruth& t) {
  if (!std::isfinite(t.lat_rad)) return "lat_rad";
  if (!std::isfinite(t.lon_rad)) return "lon_rad";
  if (!std::isfinite(t.altitude_msl_m)) return "altitude_msl_m";
  if (!finite3(t.velocity_ned_mps)) return "velocity_ned_mps";
  if (!t.q_ned_from_body.coeffs().allFinite() || t.q_ned_from_body.norm() < 0.5) {
    return "q_ned_from_body";
  }
  if (!std::isfinite(t.euler.phi_rad) || !std::isfinite(t.euler.theta_rad) ||
      !std::isfinite(t.euler.psi_rad)) {
    return "euler";
  }
  if (!std::isfinite(t.true_airspeed_mps)) return "true_airspeed_mps";
  if (!std::isfinite(t.climb_rate_mps)) return "climb_rate_mps";
  if (!finite3(t.acceleration_body_mps2)) return "acceleration_body_mps2";
  if (!finite3(t.specific_force_body_mps2)) return "specific_force_body_mps2";
  if (!finite3(t.omega_body_radps)) return "omega_body_radps";
  return {};
}

AvionicsSuite::AvionicsSuite(const radio::StationSource& stations,
                             std::span<const IlsApproach> marker_beacons, AvionicsConfig config)
    : stations_(&stations),
      marker_beacons_(marker_beacons),
      config_(std::move(config)),
      nav_{radio::NavRadio(stations, failures_.stations), radio::NavRadio(stations, failures_.stations)},
      adf_(stations, failures_.stations),
      gps_(GpsConstellation::baseline_24(), config_.gps),
      flight_director_(config_.flight_director) {
  if (!std::isfinite(config_.gps_time_at_start_s) || config_.gps_time_at_start_s < 0.0) {
    throw std::invalid_argument("gps_time_at_start_s = " +
                                std::to_string(config_.gps_time_at_start_s) +
                                ": must be a finite time since the constellation epoch, >= 0");
  }
}

radio::AircraftPose AvionicsSuite::pose_of(const AvionicsTruth& t) {
  radio::AircraftPose p;
  p.lat_rad = t.lat_rad;
  p.lon_rad = t.lon_rad;
  p.altitude_msl_m = t.altitude_msl_m;
  p.heading_true_rad = t.euler.psi_rad;
  p.pitch_rad = t.euler.theta_rad;
  p.roll_rad = t.euler.phi_rad;
  p.true_airspeed_mps = t.true_airspeed_mps;
  p.climb_rate_mps = t.climb_rate_mps;
  return p;
}

NavigationState AvionicsSuite::navigation_truth(const AvionicsTruth& t) {
  NavigationState s;
  s.position = {t.lat_rad, t.lon_rad, t.altitude_msl_m};
  s.velocity_ned_mps = t.velocity_ned_mps;
  s.q_ned_from_body = t.q_ned_from_body.normalized();
  return s;
}

ImuSample AvionicsSuite::ideal_imu(const AvionicsTruth& t) const {
  if (t.rotating_earth) return ImuSample{t.specific_force_body_mps2, t.omega_body_radps};
  // Flat earth: its rates are relative to NED and its accelerations ignore the earth's rotation
  // and curvature; the IMU of the same motion over the real earth follows from the kinematics.
  const Eigen::Vector3d acceleration_ned = t.q_ned_from_body.normalized() * t.acceleration_body_mps2;
  return imu_from_kinematics(navigation_truth(t), acceleration_ned, t.omega_body_radps);
}

void AvionicsSuite::align(const AvionicsTruth& truth) {
  if (const auto bad = truth_problem(truth); !bad.empty()) {
    throw std::invalid_argument("cannot align the INS: aircraft state field " + std::string(bad) +
                                " is not finite");
  }
  ins_.emplace(config_.ins, navigation_truth(truth));
  fd_selections_.heading_true_rad = truth.euler.psi_rad;
  fd_selections_.altitude_msl_m = truth.altitude_msl_m;
}

const AvionicsReadings& AvionicsSuite::step(const AvionicsTruth& truth, double dt_s,
                                            double sim_time_s) {
  if (const auto bad = truth_problem(truth); !bad.empty()) {
    throw std::invalid_argument("aircraft state field " + std::string(bad) + " is not finite");
  }
  if (!std::isfinite(dt_s) || dt_s < 0.0 || !std::isfinite(sim_time_s)) {
    throw std::invalid_argument("frame dt_s = " + std::to_string(dt_s) + ", sim_time_s = " +
                                std::to_string(sim_time_s) + ": must be finite, dt_s >= 0");
  }
  const radio::AircraftPose pose = pose_of(truth);
  step_radios(pose);                 // 1-3
  step_gps(truth, sim_time_s);       // 4
  step_ins(truth, dt_s);             // 5
  step_flight_director(truth, pose); // 6
  return readings_;
}

void AvionicsSuite::step_radios(const radio::AircraftPose& pose) {
  for (std::size_t i = 0; i < nav_.size(); ++i) {
    nav_[i].set_failed(failures_.nav[i]);
    readings_.nav[i] = nav_[i].receive(radios_.nav[i], pose);
  }
  adf_.set_failed(failures_.adf);
  readings_.adf = adf_.receive(radios_.adf_khz, pose);
  markers_.set_failed(failures_.markers);
  readings_.marker = markers_.read(marker_beacons_, pose, failures_.stations);
}

void AvionicsSuite::step_gps(const AvionicsTruth& truth, double sim_time_s) {
  const Eigen::Vector3d truth_ecef =
      Wgs84::ecef_from_geodetic({truth.lat_rad, truth.lon_rad, truth.altitude_msl_m});
  readings_.gps = gps_.update(config_.gps_time_at_start_s + sim_time_s, truth_ecef,
                              failures_.gps_denied);
  readings_.gps_horizontal_error_m = 0.0;
  if (readings_.gps.valid) {
    const Eigen::Vector3d error_ned = Wgs84::ned_from_ecef(truth.lat_rad, truth.lon_rad) *
                                      (readings_.gps.position_ecef_m - truth_ecef);
    readings_.gps_horizontal_error_m = error_ned.head<2>().norm();
  }
}

void AvionicsSuite::step_ins(const AvionicsTruth& truth, double dt_s) {
  if (failures_.ins) {
    ins_.reset();  // a failed INS loses its alignment; restored, it is aligned again
    readings_.ins_valid = false;
    return;
  }
  if (!ins_) {
    ins_.emplace(config_.ins, navigation_truth(truth));  // aligned on this frame's state
  } else if (dt_s > 0.0) {
    ins_->step(ideal_imu(truth), dt_s, truth.altitude_msl_m);  // an ideal baro height
  }
  readings_.ins_valid = true;
  readings_.ins = ins_->solution();
  readings_.ins_errors = ins_->errors_against(navigation_truth(truth));
}

void AvionicsSuite::step_flight_director(const AvionicsTruth& truth, const radio::AircraftPose& pose) {
  FlightDirectorInputs in;
  in.pose = pose;
  set_nav_source(readings_.nav[0], in);
  if (fd_selections_.automatic) {
    in.lateral_mode = in.course_valid ? LateralMode::kNavTrack : LateralMode::kHeadingSelect;
    in.vertical_mode =
        in.glide_slope_valid ? VerticalMode::kGlideSlopeTrack : VerticalMode::kAltitudeHold;
  } else {
    in.lateral_mode = fd_selections_.lateral;
    in.vertical_mode = fd_selections_.vertical;
  }
  in.selected_heading_true_rad = fd_selections_.heading_true_rad;
  in.selected_altitude_msl_m = fd_selections_.altitude_msl_m;
  if (truth.velocity_ned_mps.head<2>().norm() > 1.0) {
    in.ground_track_true_rad = std::atan2(truth.velocity_ned_mps.y(), truth.velocity_ned_mps.x());
  }
  readings_.fd_lateral = in.lateral_mode;
  readings_.fd_vertical = in.vertical_mode;
  readings_.fd = flight_director_.command(in);
}

}  // namespace fedsim::nav
