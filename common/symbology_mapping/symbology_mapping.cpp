#include "common/symbology_mapping/symbology_mapping.hpp"

#include "common/units/units.hpp"

#include <algorithm>
#include <cmath>

namespace fedsim::symbology_mapping {

double magnetic_variation_of_nearest(const std::vector<nav::NavaidHit>& hits) {
  return hits.empty() ? 0.0 : hits.front().navaid.magnetic_variation_rad;
}

double magnetic_variation_near(const nav::NavDatabase& db, double lat_rad, double lon_rad, double range_nm) {
  return magnetic_variation_of_nearest(db.within(lat_rad, lon_rad, range_nm * units::kNmToM));
}

double wrap_2pi(double a) {
  a = std::fmod(a, units::kTwoPi);
  return a < 0.0 ? a + units::kTwoPi : a;
}

symbology::FlightDirector flight_director(const msg::NavigationState* nav, const msg::AutopilotState* autopilot) {
  symbology::FlightDirector fd;
  auto finite_or_zero = [](double v) { return std::isfinite(v) ? v : 0.0; };
  if (autopilot != nullptr) {
    fd.on = autopilot->fma().flight_director_on() || autopilot->fma().autopilot_engaged();
    fd.pitch_valid = autopilot->fd_pitch_valid() && std::isfinite(autopilot->fd_pitch_rad());
    fd.roll_valid = autopilot->fd_roll_valid() && std::isfinite(autopilot->fd_roll_rad());
    fd.pitch_command_rad = fd.pitch_valid ? autopilot->fd_pitch_rad() : 0.0;
    fd.roll_command_rad = fd.roll_valid ? autopilot->fd_roll_rad() : 0.0;
    if (fd.on) return fd;
  }
  if (nav != nullptr) {
    const msg::FlightDirectorState& n = nav->fd();
    if (n.lateral_mode() != msg::FD_LATERAL_OFF || n.vertical_mode() != msg::FD_VERTICAL_OFF) {
      fd.on = true;
      fd.pitch_valid = n.pitch_valid() && std::isfinite(n.pitch_command_rad());
      fd.roll_valid = n.roll_valid() && std::isfinite(n.roll_command_rad());
      fd.pitch_command_rad = fd.pitch_valid ? finite_or_zero(n.pitch_command_rad()) : 0.0;
      fd.roll_command_rad = fd.roll_valid ? finite_or_zero(n.roll_command_rad()) : 0.0;
    }
  }
  return fd;
}

hud::HudInputs hud_inputs(const msg::AircraftState& s, const msg::NavigationState* nav,
                          const msg::AutopilotState* autopilot, const DisplayContext& context) {
  hud::HudInputs in;
  in.pitch_rad = s.theta_rad();
  in.roll_rad = s.phi_rad();
  in.heading_true_rad = wrap_2pi(s.psi_rad());
  in.magnetic_variation_rad = context.magnetic_variation_rad;
  in.velocity_ned_mps = {s.velocity_ned_mps()[0], s.velocity_ned_mps()[1], s.velocity_ned_mps()[2]};
  in.ias_mps = std::max(0.0, s.air().cas_mps());
  in.altitude_m = s.altitude_msl_m();
  in.vertical_speed_mps = s.climb_rate_mps();
  in.flight_director = flight_director(nav, autopilot);
  return in;
}

}  // namespace fedsim::symbology_mapping
