// An instructor's command (seed 9.4.5) as a value: what `fedsim command`, the instructor
// station's page and scenario scripts ask of the federation, checked once here before anything
// is sent. People type degrees, knots, feet, MHz and hPa (the "edge" forms below, with those units
// in the field names); make_request() checks every field and converts it to the SI request that
// travels (common/runtime/sim_command_codec turns it into a fedsim/sim_command sample).
//
// A value that is not finite, out of range or of the wrong kind is refused with a RequestError
// that names the field as the user wrote it ("reposition: lat_deg: 95 is outside -90..90").
#pragma once

#include "common/frame_clock/run_control.hpp"
#include "common/instructor/utc_time.hpp"

#include <cstdint>
#include <stdexcept>
#include <string>
#include <variant>

namespace fedsim::instructor {

class RequestError : public std::invalid_argument {
 public:
  using std::invalid_argument::invalid_argument;
};

// ---- The SI requests (what is sent) ----

using timing::RunState;  // the frame clock's run states (common/frame_clock)
struct RunStateRequest {
  RunState state = RunState::kFreeze;
};

struct RepositionRequest {
  enum class Kind { kPoint, kRunwayThreshold, kApproachGate };
  Kind kind = Kind::kPoint;
  std::string target;             // aircraft addressed ("" = all)
  std::string airport, runway;    // kRunwayThreshold, kApproachGate
  double gate_distance_m = 0.0;   // kApproachGate: from the threshold [m]
  double latitude_rad = 0.0;      // kPoint [rad]
  double longitude_rad = 0.0;     // kPoint [rad]
  double altitude_msl_m = 0.0;    // kPoint [m]
  double heading_rad = 0.0;       // kPoint: true heading, [0, 2 pi) [rad]
  double airspeed_mps = 0.0;      // true airspeed after the move, 0 = keep [m/s]
};

struct WeatherRequest {
  double wind_from_rad = 0.0;            // surface wind FROM, true, [0, 2 pi) [rad]
  double wind_speed_mps = 0.0;           // [m/s]
  double wind_gradient_mps_per_m = 0.0;  // increase of speed with height [1/s]
  int turbulence_intensity = 0;          // 0 none, 1 light, 2 moderate, 3 severe
  std::uint32_t turbulence_seed = 0;     // 0 = the flight federate's own
  double isa_deviation_k = 0.0;          // [K]
  double sea_level_pressure_pa = 0.0;    // QNH, 0 = standard [Pa]
  double visibility_m = 10000.0;         // [m]
  double cloud_base_m = 0.0;             // above ground, 0 = no cloud [m]
};

struct FailureRequest {
  std::string system;  // a failure target (failure_targets.hpp)
  bool active = true;  // true fail, false restore
};

struct TimeOfDayRequest {
  UtcTime utc;
  bool airport_lights_on = true;
};

struct RadioTuningRequest {
  std::string target;          // aircraft addressed ("" = all)
  std::uint32_t nav1_khz = 0;  // 0 = leave as it is
  std::uint32_t nav2_khz = 0;
  double obs1_rad = -1.0;      // < 0 = leave as it is [rad]
  double obs2_rad = -1.0;
  std::uint32_t adf_khz = 0;
};

struct SnapshotRequest {
  std::string channel;  // "" = every channel
  std::string tag;      // file-name tag [A-Za-z0-9_-]
};

struct ShutdownRequest {};

using InstructorRequest = std::variant<RunStateRequest, RepositionRequest, WeatherRequest,
                                       FailureRequest, TimeOfDayRequest, RadioTuningRequest,
                                       SnapshotRequest, ShutdownRequest>;

/// "freeze", "reposition (KSFO 28R gate 10.0 NM)", "fail engine1" ... for logs and the page.
std::string describe(const InstructorRequest& request);

// ---- The edge forms (what people type) ----

struct RepositionInput {
  std::string target;
  std::string airport, runway;  // a runway end: its threshold, or a gate with gate_nm > 0
  double gate_nm = 0.0;
  bool point = false;           // true: the point below instead of a runway
  double lat_deg = 0.0, lon_deg = 0.0, alt_ft = 0.0, heading_deg = 0.0;
  double kt = 0.0;              // true airspeed after the move (0 = keep)
};

struct WeatherInput {
  double wind_from_deg = 0.0, wind_kt = 0.0, gradient_kt_per_1000ft = 0.0;
  std::string turbulence = "none";  // none | light | moderate | severe
  double seed = 0.0;                // a whole number 0..4294967295
  double isa_dev_k = 0.0;
  double qnh_hpa = 0.0;             // 0 = standard
  double visibility_m = 10000.0;
  double cloud_base_ft = 0.0;       // 0 = no cloud
};

struct TuningInput {
  std::string target;
  double nav1_mhz = 0.0, nav2_mhz = 0.0;  // 0 = leave
  double obs1_deg = -1.0, obs2_deg = -1.0;  // < 0 = leave
  double adf_khz = 0.0;                   // 0 = leave
};

struct TimeOfDayInput {
  std::string utc;  // YYYY-MM-DDTHH:MM:SS
  bool lights = true;
};

// Each throws RequestError naming the field.
RunStateRequest make_run_state(const std::string& word);  // "run" | "freeze" | "reset"
RepositionRequest make_request(const RepositionInput& in);
WeatherRequest make_request(const WeatherInput& in);
RadioTuningRequest make_request(const TuningInput& in);
TimeOfDayRequest make_request(const TimeOfDayInput& in);
FailureRequest make_failure(const std::string& system, bool active);
SnapshotRequest make_snapshot(const std::string& channel, const std::string& tag);

// ---- Limits (edge units, as the messages state them) ----
inline constexpr double kMaxAltitudeFt = 60000.0;
inline constexpr double kMaxRepositionKt = 600.0;
inline constexpr double kMaxGateNm = 30.0;
inline constexpr double kMaxWindKt = 150.0;
inline constexpr double kMaxGradientKtPer1000Ft = 30.0;
inline constexpr double kMaxIsaDeviationK = 60.0;
inline constexpr double kMinQnhHpa = 870.0, kMaxQnhHpa = 1085.0;
inline constexpr double kMinVisibilityM = 10.0, kMaxVisibilityM = 200000.0;
inline constexpr double kMaxCloudBaseFt = 50000.0;

}  // namespace fedsim::instructor
