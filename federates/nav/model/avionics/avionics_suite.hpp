// The navigation federate's executive (seed node 3, Section 2.11; Chapter 6): every frame it
// reads the aircraft's true state and the radio selections, and computes, in this order (stated
// once, here and in step()):
//   1. NAV1 and NAV2: VOR or ILS localizer + glide slope, and the paired DME (common/radio);
//   2. the ADF needle (nav_radio);
//   3. the marker beacon receiver (nav_radio), hearing every ILS marker of the database;
//   4. the GPS fix (nav_gps) from the true antenna position;
//   5. the INS (nav_inertial) from an ideal IMU built from the true motion, through its sensor
//      error model;
//   6. the flight director (nav_radio) on NAV1's course and glide slope.
// Pure: no DDS; the adapter (federates/nav/nav_component.*) maps topics to these structs.
//
// Inputs (AvionicsTruth, SI, docs/frames.md): geodetic position (WGS-84, rad, m MSL), velocity
// over the ground NED [m/s], attitude q_ned_from_body and Euler angles [rad], true airspeed and
// climb rate [m/s], the CG's earth-relative acceleration in body axes [m/s^2], the specific force
// at the CG in body axes [m/s^2] (force_body_n / mass_kg), the body rate [rad/s] as the flight
// model gives it, and whether that model is the rotating WGS-84 earth (its rates include the
// earth's) or the flat earth (its NED frame taken as inertial: the IMU is then rebuilt from the
// kinematics on the real, rotating earth so that the INS sees what a real one would).
// Selections: NAV tuning (kHz, OBS magnetic rad), ADF (kHz), flight-director modes and targets.
// Failures: a receiver failed, a station off the air (StationOutages), the INS failed, GPS
// denied: each shows as an invalid reading, never as a wrong-but-valid one.
#pragma once

#include "common/math/rotation.hpp"
#include "common/radio/nav_radio.hpp"
#include "nav/model/gps/gps_receiver.hpp"
#include "nav/model/ins/inertial_navigation_system.hpp"
#include "nav/model/radio/adf_radio.hpp"
#include "nav/model/radio/flight_director.hpp"
#include "nav/model/radio/marker_receiver.hpp"

#include <Eigen/Geometry>

#include <array>
#include <optional>
#include <span>

namespace fedsim::nav {

struct AvionicsTruth {
  double lat_rad = 0.0;
  double lon_rad = 0.0;
  double altitude_msl_m = 0.0;
  Eigen::Vector3d velocity_ned_mps = Eigen::Vector3d::Zero();
  Eigen::Quaterniond q_ned_from_body = Eigen::Quaterniond::Identity();
  EulerAngles euler;                                               // 3-2-1 of q [rad]
  double true_airspeed_mps = 0.0;
  double climb_rate_mps = 0.0;                                     // + up [m/s]
  Eigen::Vector3d acceleration_body_mps2 = Eigen::Vector3d::Zero();   // w.r.t. the earth
  Eigen::Vector3d specific_force_body_mps2 = Eigen::Vector3d::Zero(); // at the CG
  Eigen::Vector3d omega_body_radps = Eigen::Vector3d::Zero();      // as the flight model gives it
  bool rotating_earth = false;
};

struct RadioSelections {
  std::array<radio::NavTuning, 2> nav{};  // NAV1, NAV2
  std::uint32_t adf_khz = 0;
};

struct FlightDirectorSelections {
  /// Automatic: NAV track while NAV1's course signal is valid (else heading select), glide slope
  /// while its glide slope is valid (else altitude hold). Otherwise the modes below.
  bool automatic = true;
  LateralMode lateral = LateralMode::kHeadingSelect;
  VerticalMode vertical = VerticalMode::kAltitudeHold;
  double heading_true_rad = 0.0;   // selected heading [rad]
  double altitude_msl_m = 0.0;     // selected altitude [m]
};

struct AvionicsFailures {
  std::array<bool, 2> nav{};
  bool adf = false;
  bool markers = false;
  bool ins = false;
  bool gps_denied = false;
  radio::StationOutages stations;
};

struct AvionicsConfig {
  InsConfig ins;
  GpsReceiverConfig gps;
  /// GPS time of the scenario's sim time 0, since the constellation epoch [s] (it sets where the
  /// satellites are).
  double gps_time_at_start_s = 0.0;
  FlightDirectorGains flight_director;
};

struct AvionicsReadings {
  std::array<radio::NavReading, 2> nav{};
  AdfReading adf;
  MarkerReading marker;
  bool ins_valid = false;
  InsSolution ins;
  NavigationErrors ins_errors;         // INS minus truth
  GpsFix gps;
  double gps_horizontal_error_m = 0.0; // fix minus truth (0 when not valid)
  LateralMode fd_lateral = LateralMode::kOff;
  VerticalMode fd_vertical = VerticalMode::kOff;
  FlightDirectorCommand fd;
};

class AvionicsSuite {
 public:
  /// `stations` and `marker_beacons` must outlive the suite. Throws std::invalid_argument for a
  /// bad configuration.
  AvionicsSuite(const radio::StationSource& stations, std::span<const IlsApproach> marker_beacons,
                AvionicsConfig config);

  /// (Re)aligns the INS on the truth (start, reset, reposition, INS restored) and sets the
  /// flight director's targets to the current heading and altitude.
  void align(const AvionicsTruth& truth);
  /// One frame of dt_s (0 while frozen: the INS and GPS hold, the radios still read) ending at
  /// sim_time_s. Throws std::invalid_argument for a non-finite truth (the adapter checks and
  /// counts it first).
  const AvionicsReadings& step(const AvionicsTruth& truth, double dt_s, double sim_time_s);

  RadioSelections& radios() { return radios_; }
  FlightDirectorSelections& flight_director() { return fd_selections_; }
  AvionicsFailures& failures() { return failures_; }
  const AvionicsReadings& readings() const { return readings_; }
  bool aligned() const { return ins_.has_value(); }

 private:
  static radio::AircraftPose pose_of(const AvionicsTruth& truth);
  static NavigationState navigation_truth(const AvionicsTruth& truth);
  ImuSample ideal_imu(const AvionicsTruth& truth) const;
  void step_radios(const radio::AircraftPose& pose);
  void step_gps(const AvionicsTruth& truth, double sim_time_s);
  void step_ins(const AvionicsTruth& truth, double dt_s);
  void step_flight_director(const AvionicsTruth& truth, const radio::AircraftPose& pose);

  const radio::StationSource* stations_;
  std::span<const IlsApproach> marker_beacons_;
  AvionicsConfig config_;
  RadioSelections radios_;
  FlightDirectorSelections fd_selections_;
  AvionicsFailures failures_;
  std::array<radio::NavRadio, 2> nav_;
  AdfRadio adf_;
  MarkerReceiver markers_;
  GpsReceiver gps_;
  std::optional<InertialNavigationSystem> ins_;
  FlightDirector flight_director_;
  AvionicsReadings readings_;
};

/// The first field of `truth` that is not finite (its name), or empty.
std::string_view truth_problem(const AvionicsTruth& truth);

}  // namespace fedsim::nav
