// The AFCS, the NAV receivers and the flight model composed in-process for batch runs (the
// closed-loop tests and the autoland Monte Carlo): every frame the localizer and glide-slope
// receivers (common/radio) read the ILS record at the aircraft's position (or, set_nav1(), a NAV
// radio tuned over a station source reads a VOR or an ILS), the AFCS steps on the
// aircraft state and those readings, its engaged channels replace the pilot's controls, and the
// flight model steps one frame. Same order and data as the flight federate hosting the AFCS,
// with no DDS. Records one FlightSample per frame, every mode transition and the touchdown.
#pragma once

#include "common/navdb/nav_records.hpp"
#include "common/radio/approach_geometry.hpp"
#include "common/radio/nav_radio.hpp"
#include "flight/model/afcs/afcs.hpp"
#include "flight/model/afcs/model_coupling.hpp"
#include "flight/model/aircraft/aircraft_model.hpp"
#include "flight/model/scenario/trim.hpp"

#include <deque>
#include <memory>
#include <optional>
#include <vector>

namespace fedsim::flight::afcs {

/// A point given in the ILS course coordinates of common/radio's approach_geometry.hpp: distance
/// before the threshold along the course line [m] (+ before it, on the approach side), distance
/// left of the course line [m], altitude MSL [m].
struct ApproachPoint {
  double before_threshold_m = 0.0;
  double left_m = 0.0;
  double altitude_m = 0.0;
};

/// One frame of the closed loop (after the model step).
struct FlightSample {
  double time_s = 0.0;
  double before_threshold_m = 0.0;  // along the course, + before the threshold [m]
  double left_of_course_m = 0.0;    // geometric, from the course line [m]
  double gear_height_m = 0.0;       // main gear above the runway [m]
  double altitude_m = 0.0;
  double cas_mps = 0.0, ground_speed_mps = 0.0, vertical_speed_mps = 0.0;
  double pitch_rad = 0.0, roll_rad = 0.0, heading_rad = 0.0, track_rad = 0.0;
  double sideslip_rad = 0.0, yaw_rate_radps = 0.0;
  double bank_command_rad = 0.0, pitch_command_rad = 0.0, path_command_rad = 0.0;  // the AFCS's
  double localizer_deviation = 0.0, glide_slope_deviation = 0.0;  // 0 when flagged
  bool localizer_valid = false, glide_slope_valid = false;
  double lat_rad = 0.0, lon_rad = 0.0;  // CG, geodetic [rad]
  double vor_deviation = 0.0;           // NAV1's VOR (set_nav1), 0 when flagged [-]
  bool vor_valid = false;
  double elevator = 0.0, aileron = 0.0, rudder = 0.0, throttle = 0.0, pitch_trim = 0.0;
  double steering = 0.0, brake = 0.0;
  bool main_gear_on_ground = false, nose_gear_on_ground = false;
  Fma fma;
};

/// The first main-gear contact.
struct Touchdown {
  double time_s = 0.0;
  double lat_rad = 0.0, lon_rad = 0.0;  // CG position [rad]
  double beyond_threshold_m = 0.0;   // along the course [m]
  double left_of_course_m = 0.0;     // [m]
  double sink_rate_mps = 0.0;        // CG descent rate at contact [m/s], + down
  double roll_rad = 0.0, pitch_rad = 0.0;
  double heading_minus_course_rad = 0.0;
  double cas_mps = 0.0, ground_speed_mps = 0.0;
};

struct ClosedLoopOptions {
  double frame_s = 0.02;                  // 50 Hz, the federation's frame
  AfcsParameters afcs;
  AircraftModel::Options model;           // defaults to RK4 on the flat earth
  /// Frames by which the ILS readings lag the aircraft: 0 reads the receivers on this frame's
  /// state; a federation's lockstep delivers the navigation federate's readings of the state one
  /// frame older (fedsim-flight --autopilot: 1). Until that many frames have passed the ILS reads
  /// flagged, as before the first navigation sample arrives. 0..10.
  int ils_delay_frames = 0;
  ClosedLoopOptions() { model.integrator = IntegrationMethod::kRk4; }
};

class ClosedLoopFlight {
 public:
  ClosedLoopFlight(AircraftPack pack, nav::IlsApproach approach, ClosedLoopOptions options = {});
  ClosedLoopFlight(const ClosedLoopFlight&) = delete;
  ClosedLoopFlight& operator=(const ClosedLoopFlight&) = delete;

  /// Trimmed straight and level at the point, heading and true airspeed with the configuration's
  /// flaps, gear and fuel kept (pilot controls = the trimmed ones); the runway plane at the
  /// threshold's elevation. The AFCS is reset (everything off).
  TrimResult start_level(const ApproachPoint& point, double heading_true_rad, double tas_mps,
                         const AircraftControls& configuration);
  /// The same at a geodetic position (alt_m: the altitude).
  TrimResult start_level_at(const GeodeticPosition& position, double heading_true_rad, double tas_mps,
                            const AircraftControls& configuration);
  /// NAV1 as the federation has it: from the next frame the AFCS's NAV port reads `radio` (a
  /// common/radio NavRadio over a station source, e.g. the navigation database's stations) tuned to
  /// `tuning`, a VOR or an ILS (nav1_signals()), instead of the ILS receivers on the approach
  /// record. nullptr: back to those. The radio must outlive its use; set_failed() on it fails NAV1.
  void set_nav1(radio::NavRadio* radio, const radio::NavTuning& tuning);
  /// NAV1's frequency and OBS (set_nav1()), changeable between frames.
  radio::NavTuning& nav1_tuning() { return nav1_tuning_; }
  /// The ILS course [rad] (true, inbound).
  double course_rad() const { return approach_.course_true_rad; }

  McpSelections& mcp() { return mcp_; }
  /// Buttons pressed in the next frame (OR-ed).
  void press(const McpButtons& buttons);
  /// The pilot's own controls (the AFCS's engaged channels replace them each frame).
  AircraftControls& pilot() { return pilot_; }
  /// One frame; returns the sample.
  const FlightSample& step();
  /// Steps until `done(sample)` or `max_s` of simulated time; true if `done` was met.
  template <class Done>
  bool run_until(Done done, double max_s) {
    const double end = time_s() + max_s;
    while (time_s() < end - 1e-9) {
      if (done(step())) return true;
    }
    return false;
  }
  void run_for(double duration_s);

  double time_s() const;
  const FlightSample& sample() const { return sample_; }
  const std::vector<FlightSample>& history() const { return history_; }
  const std::vector<ModeTransition>& transitions() const { return transitions_; }
  const std::optional<Touchdown>& touchdown() const { return touchdown_; }
  /// The largest distance from the course line on the ground after the touchdown [m].
  double max_rollout_offset_m() const { return max_rollout_offset_m_; }
  AircraftModel& model() { return *model_; }
  const AircraftModel& model() const { return *model_; }
  Afcs& afcs() { return *afcs_; }
  const nav::IlsApproach& approach() const { return approach_; }
  const radio::ApproachGeometry& geometry() const { return geometry_; }
  /// The approach coordinates of a geodetic position.
  ApproachPoint approach_point(double lat_rad, double lon_rad, double altitude_m) const;
  /// Set false to keep no history (the Monte Carlo keeps only the touchdown).
  void set_recording(bool on) { recording_ = on; }
  /// Takes the localizer or the glide slope off the air (instructor failure): the receiver
  /// then reads kStationOffAir, its numbers zeroed (common/radio's convention for a flag).
  void set_localizer_off_air(bool off) { localizer_off_air_ = off; }
  void set_glide_slope_off_air(bool off) { glide_slope_off_air_ = off; }

 private:
  void record(const AfcsInputs& in, const AfcsOutputs& out, const AircraftControls& applied);

  AircraftPack pack_;
  nav::IlsApproach approach_;
  radio::ApproachGeometry geometry_;
  ClosedLoopOptions options_;
  GearGeometry gear_;
  std::unique_ptr<AircraftModel> model_;
  std::vector<ModeTransition> transitions_;
  std::unique_ptr<Afcs> afcs_;
  McpSelections mcp_;
  McpButtons pending_;
  std::deque<AfcsIlsSignals> ils_queue_;  // the last ils_delay_frames + 1 readings, oldest first
  AircraftControls pilot_;
  FlightSample sample_;
  std::vector<FlightSample> history_;
  std::optional<Touchdown> touchdown_;
  double max_rollout_offset_m_ = 0.0;
  bool recording_ = true;
  bool localizer_off_air_ = false;
  bool glide_slope_off_air_ = false;
  radio::NavRadio* nav1_ = nullptr;
  radio::NavTuning nav1_tuning_;
};

/// The geodetic position of an approach point (the inverse of nav::course_coordinates: the
/// point of the localizer antenna's tangent plane at those course coordinates; alt_m = the
/// point's altitude).
GeodeticPosition approach_point_position(const nav::IlsApproach& approach, const radio::ApproachGeometry& geometry,
                                         const ApproachPoint& point);

}  // namespace fedsim::flight::afcs
