#include "nav/model/radio/flight_director.hpp"

#include "common/radio/nav_radio.hpp"
#include "common/radio/radio_geometry.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

namespace fedsim::nav {

namespace {

constexpr double kMinAirspeedMps = 1.0;

void require_positive(const char* name, double value, double upper = INFINITY) {
  if (!std::isfinite(value) || value <= 0.0 || value >= upper) {
    throw std::invalid_argument(std::string("FlightDirectorGains.") + name + " = " +
                                std::to_string(value) + " (must be finite, > 0" +
                                (std::isfinite(upper) ? " and < 90 deg)" : ")"));
  }
}

double flight_path_angle_rad(const radio::AircraftPose& pose) {
  if (pose.true_airspeed_mps < kMinAirspeedMps) return 0.0;
  return std::asin(std::clamp(pose.climb_rate_mps / pose.true_airspeed_mps, -1.0, 1.0));
}

}  // namespace

void set_nav_source(const radio::NavReading& nav, FlightDirectorInputs& inputs) {
  inputs.course_valid = nav.valid();
  inputs.course_true_rad = nav.course_true_rad();
  inputs.course_deviation = nav.course_deviation();
  inputs.glide_slope_valid = nav.glide_slope.valid();
  inputs.glide_slope_deviation = nav.glide_slope.valid() ? nav.glide_slope.deviation : 0.0;
  inputs.glide_path_angle_rad = nav.glide_slope.valid() ? nav.glide_slope.glide_path_angle_rad : 0.0;
}

FlightDirector::FlightDirector(FlightDirectorGains gains) : gains_(gains) {
  const FlightDirectorGains& g = gains_;
  require_positive("heading_time_constant_s", g.heading_time_constant_s);
  require_positive("bank_limit_rad", g.bank_limit_rad, units::kHalfPi);
  require_positive("intercept_at_full_scale_rad", g.intercept_at_full_scale_rad, units::kHalfPi);
  require_positive("glide_path_correction_at_full_scale", g.glide_path_correction_at_full_scale);
  require_positive("altitude_time_constant_s", g.altitude_time_constant_s);
  require_positive("max_climb_rate_mps", g.max_climb_rate_mps);
  require_positive("pitch_up_limit_rad", g.pitch_up_limit_rad, units::kHalfPi);
  require_positive("pitch_down_limit_rad", g.pitch_down_limit_rad, units::kHalfPi);
}

FlightDirectorCommand FlightDirector::command(const FlightDirectorInputs& inputs) const {
  FlightDirectorCommand out;
  if (!radio::pose_problem(inputs.pose).empty()) return out;
  if (const auto roll = roll_command(inputs)) {
    out.roll_command_rad = *roll;
    out.roll_valid = true;
  }
  if (const auto pitch = pitch_command(inputs)) {
    out.pitch_command_rad = *pitch;
    out.pitch_valid = true;
  }
  return out;
}

std::optional<double> FlightDirector::roll_command(const FlightDirectorInputs& in) const {
  const double airspeed_mps = in.pose.true_airspeed_mps;
  switch (in.lateral_mode) {
    case LateralMode::kOff: return std::nullopt;
    case LateralMode::kHeadingSelect: {
      if (!std::isfinite(in.selected_heading_true_rad)) return std::nullopt;
      const double error_rad =
          wrap_pi(in.selected_heading_true_rad - in.pose.heading_true_rad);
      return bank_for_direction_error(error_rad, airspeed_mps);
    }
    case LateralMode::kNavTrack: {
      if (!in.course_valid || !std::isfinite(in.course_true_rad) ||
          !std::isfinite(in.course_deviation)) {
        return std::nullopt;
      }
      if (in.ground_track_true_rad && !std::isfinite(*in.ground_track_true_rad)) {
        return std::nullopt;
      }
      const double intercept_rad =
          gains_.intercept_at_full_scale_rad * std::clamp(in.course_deviation, -1.0, 1.0);
      const double direction_rad = in.ground_track_true_rad.value_or(in.pose.heading_true_rad);
      const double error_rad =
          wrap_pi(in.course_true_rad + intercept_rad - direction_rad);
      return bank_for_direction_error(error_rad, airspeed_mps);
    }
  }
  return std::nullopt;
}

std::optional<double> FlightDirector::pitch_command(const FlightDirectorInputs& in) const {
  switch (in.vertical_mode) {
    case VerticalMode::kOff: return std::nullopt;
    case VerticalMode::kAltitudeHold: {
      if (!std::isfinite(in.selected_altitude_msl_m)) return std::nullopt;
      const double climb_command_mps =
          std::clamp((in.selected_altitude_msl_m - in.pose.altitude_msl_m) /
                         gains_.altitude_time_constant_s,
                     -gains_.max_climb_rate_mps, gains_.max_climb_rate_mps);
      const double airspeed_mps = in.pose.true_airspeed_mps;
      const double gamma_command_rad =
          airspeed_mps < kMinAirspeedMps
              ? 0.0
              : std::asin(std::clamp(climb_command_mps / airspeed_mps, -1.0, 1.0));
      return pitch_for_flight_path(gamma_command_rad, in.pose);
    }
    case VerticalMode::kGlideSlopeTrack: {
      if (!in.glide_slope_valid || !std::isfinite(in.glide_slope_deviation) ||
          !std::isfinite(in.glide_path_angle_rad) || in.glide_path_angle_rad <= 0.0) {
        return std::nullopt;
      }
      const double theta_gs = in.glide_path_angle_rad;
      const double gamma_command_rad =
          -theta_gs + gains_.glide_path_correction_at_full_scale * theta_gs *
                          std::clamp(in.glide_slope_deviation, -1.0, 1.0);
      return pitch_for_flight_path(gamma_command_rad, in.pose);
    }
  }
  return std::nullopt;
}

double FlightDirector::bank_for_direction_error(double error_rad, double airspeed_mps) const {
  const double turn_rate_radps = error_rad / gains_.heading_time_constant_s;
  const double bank_rad =
      std::atan(airspeed_mps * turn_rate_radps / units::kStandardGravityMps2);
  return std::clamp(bank_rad, -gains_.bank_limit_rad, gains_.bank_limit_rad);
}

double FlightDirector::pitch_for_flight_path(double gamma_command_rad,
                                             const radio::AircraftPose& pose) const {
  const double pitch_rad = pose.pitch_rad + (gamma_command_rad - flight_path_angle_rad(pose));
  return std::clamp(pitch_rad, -gains_.pitch_down_limit_rad, gains_.pitch_up_limit_rad);
}

}  // namespace fedsim::nav
