#include "flight/model/afcs/closed_loop_flight.hpp"

#include <stdexcept>
#include <string>

#include "common/radio/glide_slope_receiver.hpp"
#include "common/radio/localizer_receiver.hpp"
#include "flight/model/afcs/lateral_guidance.hpp"
#include "flight/model/scenario/reposition.hpp"

#include <GeographicLib/LocalCartesian.hpp>

#include <algorithm>
#include <cmath>

namespace fedsim::flight::afcs {

GeodeticPosition approach_point_position(const nav::IlsApproach& approach, const radio::ApproachGeometry& geometry,
                                         const ApproachPoint& point) {
  const nav::GeoPoint& antenna = approach.localizer;
  const GeographicLib::LocalCartesian plane(antenna.lat_rad * units::kRadToDeg, antenna.lon_rad * units::kRadToDeg,
                                            antenna.elevation_m);
  const double along = geometry.threshold_along_m + point.before_threshold_m;
  const double b = geometry.localizer_back_azimuth_rad;
  const double north = along * std::cos(b) - point.left_m * std::sin(b);
  const double east = along * std::sin(b) + point.left_m * std::cos(b);
  double lat = 0.0, lon = 0.0, h = 0.0;
  plane.Reverse(east, north, 0.0, lat, lon, h);
  return {lat * units::kDegToRad, lon * units::kDegToRad, point.altitude_m};
}

ClosedLoopFlight::ClosedLoopFlight(AircraftPack pack, nav::IlsApproach approach, ClosedLoopOptions options)
    : pack_(std::move(pack)),
      approach_(std::move(approach)),
      geometry_(radio::approach_geometry(approach_)),
      options_(std::move(options)),
      gear_(GearGeometry::of(pack_)),
      model_(std::make_unique<AircraftModel>(pack_, options_.model)),
      afcs_(std::make_unique<Afcs>(options_.afcs, options_.frame_s,
                                   [this](const ModeTransition& t) { transitions_.push_back(t); })) {
  if (options_.ils_delay_frames < 0 || options_.ils_delay_frames > 10) {
    throw std::invalid_argument("ClosedLoopOptions.ils_delay_frames must be within 0..10 (got " +
                                std::to_string(options_.ils_delay_frames) + ")");
  }
}

TrimResult ClosedLoopFlight::start_level(const ApproachPoint& point, double heading_true_rad, double tas_mps,
                                         const AircraftControls& configuration) {
  return start_level_at(approach_point_position(approach_, geometry_, point), heading_true_rad, tas_mps,
                        configuration);
}

void ClosedLoopFlight::set_nav1(radio::NavRadio* radio, const radio::NavTuning& tuning) {
  nav1_ = radio;
  nav1_tuning_ = tuning;
}

TrimResult ClosedLoopFlight::start_level_at(const GeodeticPosition& position, double heading_true_rad,
                                            double tas_mps, const AircraftControls& configuration) {
  model_->set_controls(configuration);
  model_->set_runway_elevation_m(approach_.threshold.elevation_m);
  const TrimResult trim = reposition_to_point(*model_, position, heading_true_rad, tas_mps);
  pilot_ = trim.controls;
  afcs_->reset();
  transitions_.clear();
  history_.clear();
  touchdown_.reset();
  max_rollout_offset_m_ = 0.0;
  pending_ = McpButtons{};
  ils_queue_.clear();
  mcp_.heading_true_rad = heading_true_rad;
  mcp_.altitude_m = position.alt_m;
  mcp_.calibrated_airspeed_mps = std::clamp(model_->outputs().cas_mps, 40.0, 200.0);
  sample_ = FlightSample{};
  return trim;
}

void ClosedLoopFlight::press(const McpButtons& b) { pending_ |= b; }

double ClosedLoopFlight::time_s() const { return model_->time_s(); }

void ClosedLoopFlight::run_for(double duration_s) {
  const double end = time_s() + duration_s;
  while (time_s() < end - 1e-9) step();
}

ApproachPoint ClosedLoopFlight::approach_point(double lat_rad, double lon_rad, double altitude_m) const {
  const radio::CourseCoordinates cc = radio::course_coordinates(approach_, geometry_, lat_rad, lon_rad);
  return {cc.along_m - geometry_.threshold_along_m, cc.left_m, altitude_m};
}

const FlightSample& ClosedLoopFlight::step() {
  const AircraftOutputs& o = model_->outputs();
  const radio::AircraftPose pose = nav_pose(o);
  radio::LocalizerReading loc = radio::LocalizerReceiver().read(approach_, pose);
  radio::GlideSlopeReading gs = radio::GlideSlopeReceiver().read(approach_, pose);
  if (localizer_off_air_) loc = radio::LocalizerReading{radio::SignalStatus::kStationOffAir, loc.ident};
  if (glide_slope_off_air_) gs = radio::GlideSlopeReading{radio::SignalStatus::kStationOffAir, gs.ident};
  AfcsInputs in;
  in.aircraft = afcs_aircraft_state(o, pack_, gear_, pilot_);
  ils_queue_.push_back(nav1_ != nullptr ? nav1_signals(nav1_->receive(nav1_tuning_, pose), pose)
                                        : ils_signals(loc, gs, approach_, geometry_, pose));
  const auto delay = static_cast<std::size_t>(options_.ils_delay_frames);
  in.ils = ils_queue_.size() > delay ? ils_queue_.front() : AfcsIlsSignals{};
  if (ils_queue_.size() > delay) ils_queue_.pop_front();
  in.buttons = pending_;
  in.mcp = mcp_;
  pending_ = McpButtons{};
  const AfcsOutputs& out = afcs_->step(in);
  const AircraftControls applied = apply_afcs_outputs(out, pilot_, o.pitch_trim_norm);
  // The autopilot's servos and the autothrottle back-drive column, wheel, pedals and levers,
  // and trim switches are momentary: where the AFCS leaves a control, the pilot finds it.
  if (out.autopilot_engaged) {
    pilot_.elevator_trim = o.pitch_trim_norm;
    pilot_.elevator = applied.elevator;
    pilot_.aileron = applied.aileron;
    pilot_.rudder = applied.rudder;
  }
  if (out.autothrottle_engaged) pilot_.throttle = applied.throttle;
  model_->set_controls(applied);
  model_->step(options_.frame_s);
  record(in, out, applied);
  return sample_;
}

void ClosedLoopFlight::record(const AfcsInputs& in, const AfcsOutputs& out, const AircraftControls& applied) {
  const AircraftOutputs& o = model_->outputs();
  const FlightSample before = sample_;
  FlightSample s;
  s.time_s = o.time_s;
  const ApproachPoint p = approach_point(o.geodetic.lat_rad, o.geodetic.lon_rad, o.geodetic.alt_m);
  s.before_threshold_m = p.before_threshold_m;
  s.left_of_course_m = p.left_m;
  s.gear_height_m = main_gear_height_m(o, pack_, gear_);
  s.altitude_m = o.geodetic.alt_m;
  s.cas_mps = o.cas_mps;
  s.ground_speed_mps = o.ground_speed_mps;
  s.vertical_speed_mps = o.climb_rate_mps;
  s.pitch_rad = o.euler.theta_rad;
  s.roll_rad = o.euler.phi_rad;
  s.heading_rad = o.euler.psi_rad;
  s.track_rad = o.ground_speed_mps > 1.0 ? std::atan2(o.velocity_ned_mps.y(), o.velocity_ned_mps.x()) : s.heading_rad;
  s.sideslip_rad = o.beta_rad;
  s.bank_command_rad = out.flight_director_roll_rad;
  s.pitch_command_rad = out.flight_director_pitch_rad;
  s.path_command_rad = out.flight_path_command_rad;
  s.yaw_rate_radps = o.omega_body_wrt_earth_radps.z();
  s.localizer_valid = in.ils.localizer_valid;
  s.localizer_deviation = in.ils.localizer_deviation;
  s.glide_slope_valid = in.ils.glide_slope_valid;
  s.glide_slope_deviation = in.ils.glide_slope_deviation;
  s.lat_rad = o.geodetic.lat_rad;
  s.lon_rad = o.geodetic.lon_rad;
  s.vor_valid = in.ils.vor.valid;
  s.vor_deviation = in.ils.vor.deviation;
  s.elevator = applied.elevator;
  s.aileron = applied.aileron;
  s.rudder = applied.rudder;
  s.throttle = applied.throttle[0];
  s.pitch_trim = o.pitch_trim_norm;
  s.steering = applied.steering;
  s.brake = std::max(applied.brake_left, applied.brake_right);
  const AfcsAircraftState a = afcs_aircraft_state(o, pack_, gear_, applied);
  s.main_gear_on_ground = a.main_gear_on_ground;
  s.nose_gear_on_ground = a.nose_gear_on_ground;
  s.fma = out.fma;
  if (!touchdown_ && s.main_gear_on_ground && before.time_s > 0.0 && !before.main_gear_on_ground) {
    Touchdown t;
    t.time_s = s.time_s;
    t.lat_rad = o.geodetic.lat_rad;
    t.lon_rad = o.geodetic.lon_rad;
    t.beyond_threshold_m = -s.before_threshold_m;
    t.left_of_course_m = s.left_of_course_m;
    t.sink_rate_mps = std::max(-before.vertical_speed_mps, -s.vertical_speed_mps);
    t.roll_rad = s.roll_rad;
    t.pitch_rad = s.pitch_rad;
    t.heading_minus_course_rad = wrap_angle_rad(s.heading_rad - approach_.course_true_rad);
    t.cas_mps = s.cas_mps;
    t.ground_speed_mps = s.ground_speed_mps;
    touchdown_ = t;
  }
  if (touchdown_) max_rollout_offset_m_ = std::max(max_rollout_offset_m_, std::abs(s.left_of_course_m));
  sample_ = s;
  if (recording_) history_.push_back(s);
}

}  // namespace fedsim::flight::afcs
