#include "flight/federate/replay_playback.hpp"

#include <cmath>

namespace fedsim::flight {

ReplayPlayback::Event ReplayPlayback::update(std::uint64_t updates, const msg::AircraftState* latest,
                                             std::string& problem) {
  problem.clear();
  bool fresh = false;
  if (latest != nullptr && updates != seen_updates_) {
    seen_updates_ = updates;
    problem = replay_sample_problem(*latest);
    if (problem.empty()) {
      last_ = *latest;
      ++samples_;
      fresh = true;
    }
  }
  frames_since_sample_ = fresh ? 0 : frames_since_sample_ + 1;
  if (fresh && !active_) {
    active_ = true;
    return Event::kStarted;
  }
  if (active_ && frames_since_sample_ >= kHoldFrames) {
    active_ = false;
    return Event::kEnded;
  }
  return Event::kNone;
}

std::string replay_sample_problem(const msg::AircraftState& s) {
  const auto finite3 = [](const std::array<double, 3>& v) {
    return std::isfinite(v[0]) && std::isfinite(v[1]) && std::isfinite(v[2]);
  };
  if (!std::isfinite(s.latitude_rad()) || std::abs(s.latitude_rad()) > 0.5 * M_PI) return "latitude_rad";
  if (!std::isfinite(s.longitude_rad())) return "longitude_rad";
  if (!std::isfinite(s.altitude_msl_m())) return "altitude_msl_m";
  if (!finite3(s.velocity_ned_mps())) return "velocity_ned_mps";
  if (!std::isfinite(s.phi_rad()) || !std::isfinite(s.theta_rad()) || !std::isfinite(s.psi_rad())) return "phi/theta/psi_rad";
  if (!finite3(s.omega_body_radps())) return "omega_body_radps";
  return {};
}

AircraftInitialConditions state_from_replay(const msg::AircraftState& s) {
  AircraftInitialConditions ic;
  ic.position = GeodeticPosition{s.latitude_rad(), s.longitude_rad(), s.altitude_msl_m()};
  ic.velocity_frame = AircraftInitialConditions::VelocityFrame::kNed;
  ic.velocity_mps = Eigen::Vector3d(s.velocity_ned_mps()[0], s.velocity_ned_mps()[1], s.velocity_ned_mps()[2]);
  ic.attitude = EulerAngles{s.phi_rad(), s.theta_rad(), s.psi_rad()};
  ic.omega_body_radps = Eigen::Vector3d(s.omega_body_radps()[0], s.omega_body_radps()[1], s.omega_body_radps()[2]);
  ic.omega_relative_to_earth = false;  // the message's rates are w.r.t. inertial space
  return ic;
}

}  // namespace fedsim::flight
