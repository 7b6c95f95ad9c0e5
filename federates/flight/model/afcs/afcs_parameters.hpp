// Gains, limits and heights of the AFCS, SI. The defaults are the 737 pack's (data/aircraft/
// b737.yaml), designed at the approach point (145 KCAS, flaps 30, 48.5 t) from the pack's own
// derivatives and verified closed loop (README.md, "Control laws"); gains that act through
// dynamic pressure are scheduled by (reference CAS / CAS)^2.
// AfcsParameters::validate() throws std::invalid_argument naming the first bad field.
#pragma once

#include "common/units/units.hpp"

namespace fedsim::flight::afcs {

/// Pitch attitude -> elevator (inner loop), per unit of normalised elevator command.
struct PitchLoopGains {
  double attitude_gain_per_rad = 8.0;        // K_theta
  double integral_gain_per_rad_s = 2.0;      // K_theta_i: holds the trim elevator
  double rate_gain_per_radps = 6.0;          // K_q: short-period damping
};

/// Bank -> aileron (inner loop).
struct RollLoopGains {
  double attitude_gain_per_rad = 6.0;
  double integral_gain_per_rad_s = 1.0;
  double rate_gain_per_radps = 3.5;
  double bank_rate_limit_radps = 5.0 * units::kDegToRad;  // roll-command rate (comfort)
};

/// Rudder: turn coordination (sideslip to zero) and the decrab of ALIGN.
struct YawChannelGains {
  double sideslip_gain_per_rad = 2.0;
  double sideslip_integral_gain_per_rad_s = 1.0;
  double align_heading_gain_per_rad = 4.0;      // rudder per rad of heading error in ALIGN
  double align_heading_integral_per_rad_s = 2.0;
  double align_yaw_rate_gain_per_radps = 3.0;
  double align_heading_rate_radps = 3.0 * units::kDegToRad;  // decrab rate of the heading command
};

/// Flight-path angle -> pitch attitude (the path loop every path mode flies through).
struct FlightPathGains {
  double proportional_gain = 1.0;       // rad of pitch per rad of flight-path error
  double integral_gain_per_s = 0.4;     // ~ 1 / (the path lag 1/Z_alpha at approach, 2.3 s)
  double pitch_min_rad = -10.0 * units::kDegToRad;
  double pitch_max_rad = 20.0 * units::kDegToRad;
  double turn_compensation_rad = 18.0 * units::kDegToRad;  // CL/CL_alpha at the reference CAS
  double path_lag_s = 2.3;  // 1/Z_alpha at approach: the flare's pitch lead (T x d gamma_c/dt)
};

/// Altitude capture and hold.
struct AltitudeGains {
  double time_constant_s = 8.0;          // final exponential approach and hold: hdot = dh / tau
  double capture_acceleration_mps2 = 0.05 * units::kStandardGravityMps2;  // 0.05 g level-off
  double hold_band_m = 20.0 * units::kFtToM;  // ALT ACQ -> ALT HOLD within it
  double max_hold_rate_mps = 1000.0 * units::kFpmToMps;
};

/// Speed on the elevator (level change and go-around).
struct SpeedOnElevatorGains {
  double time_constant_s = 10.0;         // gamma_c = (CAS - CAS_sel) / (g tau) + integral
  double integral_time_s = 20.0;
  double max_climb_path_rad = 12.0 * units::kDegToRad;
  double min_descent_path_rad = -8.0 * units::kDegToRad;
  double go_around_min_path_rad = 1.0 * units::kDegToRad;
  double go_around_pitch_max_rad = 15.0 * units::kDegToRad;
  double go_around_climb_rate_mps = 2000.0 * units::kFpmToMps;  // GA thrust target
};

/// Glide slope: capture and track on the linear height error (distance-compensated).
struct GlideSlopeGains {
  double path_time_constant_s = 10.0;    // height error decays as exp(-t / tau)
  double capture_margin_rad = 0.25 * units::kDegToRad;
  double max_descent_factor = 2.0;       // gamma_c >= -factor x theta_gs
  double max_on_scale_deviation = 0.95;  // capture only on scale
};

/// Heading, track and localizer.
struct LateralGains {
  double heading_time_constant_s = 6.0;  // direction error decays as exp(-t / tau)
  double localizer_time_constant_s = 16.0;  // cross-track decay on the localizer
  double max_intercept_rad = 45.0 * units::kDegToRad;
  double approach_bank_limit_rad = 25.0 * units::kDegToRad;
  double capture_bank_rad = 20.0 * units::kDegToRad;  // the capture point's nominal bank
  double roll_in_time_s = 2.0;           // lead added for the roll into the capture turn
  double max_on_scale_deviation = 0.95;
  double low_height_bank_limit_rad = 5.0 * units::kDegToRad;  // in ALIGN
  double side_force_filter_s = 1.0;  // low-pass of the lateral specific force (ALIGN's slip bank)
};

/// VOR tracking (VOR/LOC on a VOR). The beam is 10 deg full scale against the localizer's ~2-3
/// deg, and a real one is noisier (scalloping, site errors; common/radio's is exact): the law is
/// the localizer's on the lateral distance (DME x angle), with a softer time constant and the
/// deviation low-passed.
struct VorGains {
  double track_time_constant_s = 20.0;  // cross-track decay (the localizer's: 16 s)
  double deviation_filter_s = 1.0;      // low-pass of the deviation (its lag is added to the capture lead)
  // Without DME: the distance assumed when the VOR is first received (or the DME lost: then
  // the last DME distance), dead-reckoned along the course (TO: closing, FROM: opening) within
  // [min, max], the minimum after a station passage.
  double nominal_distance_m = 15.0 * units::kNmToM;
  double min_nominal_distance_m = 5.0 * units::kNmToM;
  double max_nominal_distance_m = 60.0 * units::kNmToM;
  // Station passage: entered on the cone-of-confusion flag, a deviation moving faster than
  // erratic_rate (full scale per second, low-passed over erratic_filter_s) or the TO/FROM flag
  // turning from TO to FROM; the course is held until over_station_hold_s after the last of these
  // (and the signal valid); a flag still there after max_over_station_s is a failure.
  double erratic_rate_per_s = 0.1;      // 1 deg/s: 5x the rate of a 45 deg intercept at 5 NM, 290 kt
  double erratic_filter_s = 0.5;
  double over_station_hold_s = 10.0;
  double max_over_station_s = 120.0;    // the cone at FL350 is 12 km across: 50 s at 480 kt
};

/// Autoland heights and the flare.
struct AutolandGains {
  double flare_arm_height_m = 1500.0 * units::kFtToM;
  double align_height_m = 35.0 * units::kFtToM;
  double flare_height_m = 50.0 * units::kFtToM;
  double retard_height_m = 27.0 * units::kFtToM;  // 737 autoland "RETARD" at 27 ft RA
  double touchdown_sink_rate_mps = 1.0 * units::kFtToM;  // the flare law's asymptote
  double flare_extra_path_gain = 1.5;  // FLARE's path error gain beyond the path loop's (P only)
  double derotation_rate_radps = 1.5 * units::kDegToRad;
  double rollout_pitch_rad = 0.0;
};

/// Rollout on the localizer and the autobrake.
struct RolloutGains {
  double cross_track_gain_per_m = 0.02;     // steering per m left of the centreline
  double heading_gain_per_rad = 1.5;        // steering per rad of heading error
  double yaw_rate_gain_per_radps = 1.5;
  double rudder_scale = 2.0;                // rudder = PI(the steering law): proportional part
  double rudder_integral_per_s = 1.0;       // ... and its integral (holds a crosswind's rudder)
  double steering_limit = 0.2;              // of the nose wheel's full travel
  double taxi_speed_mps = 1.0;              // "stopped" below it
  double autobrake_delay_s = 1.0;           // after main-gear touchdown
  // Deceleration targets of autobrake settings 1, 2, 3 and MAX (737: 4, 5, 7.2, 14 ft/s^2).
  double deceleration_1_mps2 = 4.0 * units::kFtToM;
  double deceleration_2_mps2 = 5.0 * units::kFtToM;
  double deceleration_3_mps2 = 7.2 * units::kFtToM;
  double deceleration_max_mps2 = 14.0 * units::kFtToM;
  double brake_proportional_per_mps2 = 0.1;   // the brakes give ~4 m/s^2 per unit: loop gain 0.4
  double brake_integral_per_mps2_s = 0.3;
  double deceleration_filter_s = 0.3;
  double brake_rate_per_s = 1.0;              // pressure build-up
  double spoiler_rate_per_s = 2.0;
};

/// Autothrottle.
struct AutothrottleGains {
  double speed_proportional_per_mps = 0.05;   // throttle per m/s of CAS error
  double speed_integral_per_mps_s = 0.01;
  double speed_derivative_s = 0.15;            // on the CAS error (filtered)
  double derivative_filter_s = 1.0;
  double climb_rate_proportional_per_mps = 0.05;  // GA thrust on the climb-rate error
  double climb_rate_integral_per_mps_s = 0.01;
  double lever_rate_per_s = 0.15;
  double retard_rate_per_s = 0.25;
  double climb_throttle = 0.95;
  double idle_throttle = 0.0;
};

struct AfcsParameters {
  double reference_cas_mps = 145.0 * units::kKtToMps;  // gain-schedule design point
  double min_gain_schedule = 0.25;
  double max_gain_schedule = 4.0;
  double fade_time_s = 2.0;          // mode-change faders
  double command_rate_filter_s = 0.5;  // smoothing of the attitude commands' rates (rate damping reference)
  double cws_pitch_rate_radps = 3.0 * units::kDegToRad;  // per unit of column force
  double cws_roll_rate_radps = 6.0 * units::kDegToRad;
  // Control-wheel steering from the force transducers (fedsim/pilot_controls pilot_force_n, with
  // DISCRETE_FORCE_SENSORS): no input within the breakout (the transducers' detent), then linear
  // to full input (the rates above) at the full force, held beyond it. The 737 maintenance
  // manual (22-11-00, CWS force transducers) describes signals proportional to the force with an
  // out-of-detent threshold, and the FCOM says CWS takes "control pressure similar to that
  // required for manual flight", but neither gives the forces: these are fedsim's choice. Full
  // input at half the one-hand short-term forces of 14 CFR 25.143(d) (pitch 50 lbf, roll 25 lbf),
  // i.e. a firm one-hand pull or turn, well short of what a pilot can hold only briefly; the
  // breakout (2.2 lbf) above a hand resting on the controls and the control loader's friction.
  double cws_breakout_force_n = 10.0;
  double cws_full_column_force_n = 111.0;  // 25 lbf
  double cws_full_wheel_force_n = 56.0;    // 12.5 lbf
  double engage_bank_limit_rad = 30.0 * units::kDegToRad;
  double engage_pitch_min_rad = -10.0 * units::kDegToRad;
  double engage_pitch_max_rad = 20.0 * units::kDegToRad;
  double authority_bank_limit_rad = 45.0 * units::kDegToRad;
  double authority_pitch_min_rad = -15.0 * units::kDegToRad;
  double authority_pitch_max_rad = 25.0 * units::kDegToRad;
  double wings_level_bank_rad = 6.0 * units::kDegToRad;
  // Auto-trim acts on the elevator low-passed over trim_filter_s (the steady load, not the
  // manoeuvring): it runs while that exceeds trim_start for trim_delay, until below trim_stop,
  // in pulses whose duty is the gain schedule (the trim's moment grows with qbar: "when airspeed
  // increases, the trim rate decreases", as Boeing's autopilot trim does).
  double trim_start_elevator = 0.05;
  double trim_stop_elevator = 0.01;
  double trim_delay_s = 2.0;
  double trim_filter_s = 1.0;
  bool auto_trim = true;              // false: no trim command (an aircraft without a trim motor)
  PitchLoopGains pitch;
  RollLoopGains roll;
  YawChannelGains yaw;
  FlightPathGains path;
  AltitudeGains altitude;
  SpeedOnElevatorGains speed_on_elevator;
  GlideSlopeGains glide_slope;
  LateralGains lateral;
  VorGains vor;
  AutolandGains autoland;
  RolloutGains rollout;
  AutothrottleGains autothrottle;

  void validate() const;
};

}  // namespace fedsim::flight::afcs
