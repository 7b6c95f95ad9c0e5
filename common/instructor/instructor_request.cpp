#include "common/instructor/instructor_request.hpp"

#include "common/instructor/failure_targets.hpp"
#include "common/units/units.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>

namespace fedsim::instructor {

namespace {

std::string number_text(double v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%g", v);
  return buf;
}

/// Refuses a value that is not finite or lies outside [lo, hi], naming `what` and `field`.
double within(const char* what, const char* field, double v, double lo, double hi) {
  if (!std::isfinite(v)) {
    throw RequestError(std::string(what) + ": " + field + ": " + number_text(v) + " is not a finite number");
  }
  if (v < lo || v > hi) {
    throw RequestError(std::string(what) + ": " + field + ": " + number_text(v) + " is outside " +
                       number_text(lo) + ".." + number_text(hi));
  }
  return v;
}

/// An angle typed in degrees, one turn either way, carried in [0, 2 pi) [rad].
double direction_rad(const char* what, const char* field, double deg) {
  within(what, field, deg, -360.0, 360.0);
  double rad = std::fmod(deg, 360.0) * units::kDegToRad;
  if (rad < 0.0) rad += 2.0 * units::kPi;
  return rad;
}

bool only_chars(const std::string& s, const char* allowed) {
  return s.find_first_not_of(allowed) == std::string::npos;
}

constexpr const char* kIdentChars = "ABCDEFGHIJKLMNOPQRSTUVWXYZ0123456789";
constexpr const char* kTagChars = "abcdefghijklmnopqrstuvwxyzABCDEFGHIJKLMNOPQRSTUVWXYZ0123456789_-";

std::string checked_target(const char* what, const std::string& target) {
  if (target.size() > 32 || !only_chars(target, kTagChars)) {
    throw RequestError(std::string(what) + ": target: '" + target + "': up to 32 characters of [A-Za-z0-9_-]");
  }
  return target;
}

/// A VHF NAV frequency as dialled: the 50 kHz channel nearest the MHz typed.
std::uint32_t nav_channel_khz(const char* field, double mhz) {
  if (mhz == 0.0) return 0;
  within("tune", field, mhz, 108.0, 117.95);
  return static_cast<std::uint32_t>(std::lround(mhz * 20.0)) * 50u;
}

}  // namespace

RunStateRequest make_run_state(const std::string& word) {
  if (word == "run") return {RunState::kRun};
  if (word == "freeze") return {RunState::kFreeze};
  if (word == "reset") return {RunState::kReset};
  throw RequestError("run state: '" + word + "': one of run, freeze, reset");
}

RepositionRequest make_request(const RepositionInput& in) {
  constexpr const char* what = "reposition";
  RepositionRequest r;
  r.target = checked_target(what, in.target);
  r.airspeed_mps = within(what, "kt", in.kt, 0.0, kMaxRepositionKt) * units::kKtToMps;
  if (in.point) {
    r.kind = RepositionRequest::Kind::kPoint;
    r.latitude_rad = within(what, "lat_deg", in.lat_deg, -90.0, 90.0) * units::kDegToRad;
    r.longitude_rad = within(what, "lon_deg", in.lon_deg, -180.0, 180.0) * units::kDegToRad;
    r.altitude_msl_m = within(what, "alt_ft", in.alt_ft, -1500.0, kMaxAltitudeFt) * units::kFtToM;
    r.heading_rad = direction_rad(what, "heading_deg", in.heading_deg);
    return r;
  }
  if (in.airport.empty() || in.runway.empty()) {
    throw RequestError("reposition: give a point (lat_deg, lon_deg, alt_ft, heading_deg) or an "
                       "airport and runway (and gate_nm for an approach gate)");
  }
  if (in.airport.size() > 8 || !only_chars(in.airport, kIdentChars)) {
    throw RequestError("reposition: airport: '" + in.airport + "': an ICAO ident, up to 8 of [A-Z0-9]");
  }
  if (in.runway.size() > 8 || !only_chars(in.runway, kIdentChars)) {
    throw RequestError("reposition: runway: '" + in.runway + "': a designator such as 28R");
  }
  r.airport = in.airport;
  r.runway = in.runway;
  const double gate_nm = within(what, "gate_nm", in.gate_nm, 0.0, kMaxGateNm);
  r.kind = gate_nm > 0.0 ? RepositionRequest::Kind::kApproachGate
                         : RepositionRequest::Kind::kRunwayThreshold;
  r.gate_distance_m = gate_nm * units::kNmToM;
  return r;
}

WeatherRequest make_request(const WeatherInput& in) {
  constexpr const char* what = "weather";
  WeatherRequest w;
  w.wind_from_rad = direction_rad(what, "wind_from_deg", in.wind_from_deg);
  w.wind_speed_mps = within(what, "wind_kt", in.wind_kt, 0.0, kMaxWindKt) * units::kKtToMps;
  w.wind_gradient_mps_per_m =
      within(what, "gradient_kt_per_1000ft", in.gradient_kt_per_1000ft, -kMaxGradientKtPer1000Ft,
             kMaxGradientKtPer1000Ft) *
      units::kKtToMps / (1000.0 * units::kFtToM);
  static constexpr std::array<const char*, 4> kLevels{"none", "light", "moderate", "severe"};
  const auto level = std::find(kLevels.begin(), kLevels.end(), in.turbulence);
  if (level == kLevels.end()) {
    throw RequestError("weather: turbulence: '" + in.turbulence + "': one of none, light, moderate, severe");
  }
  w.turbulence_intensity = static_cast<int>(level - kLevels.begin());
  const double seed = within(what, "seed", in.seed, 0.0, 4294967295.0);
  if (seed != std::floor(seed)) throw RequestError("weather: seed: " + number_text(seed) + " is not a whole number");
  w.turbulence_seed = static_cast<std::uint32_t>(seed);
  w.isa_deviation_k = within(what, "isa_dev_k", in.isa_dev_k, -kMaxIsaDeviationK, kMaxIsaDeviationK);
  if (in.qnh_hpa != 0.0) {
    w.sea_level_pressure_pa = within(what, "qnh_hpa", in.qnh_hpa, kMinQnhHpa, kMaxQnhHpa) * 100.0;
  }
  w.visibility_m = within(what, "visibility_m", in.visibility_m, kMinVisibilityM, kMaxVisibilityM);
  w.cloud_base_m = within(what, "cloud_base_ft", in.cloud_base_ft, 0.0, kMaxCloudBaseFt) * units::kFtToM;
  return w;
}

RadioTuningRequest make_request(const TuningInput& in) {
  RadioTuningRequest r;
  r.target = checked_target("tune", in.target);
  r.nav1_khz = nav_channel_khz("nav1_mhz", in.nav1_mhz);
  r.nav2_khz = nav_channel_khz("nav2_mhz", in.nav2_mhz);
  if (in.adf_khz != 0.0) r.adf_khz = static_cast<std::uint32_t>(std::lround(within("tune", "adf_khz", in.adf_khz, 190.0, 1750.0)));
  if (!(in.obs1_deg < 0.0)) r.obs1_rad = within("tune", "obs1_deg", in.obs1_deg, 0.0, 360.0) * units::kDegToRad;
  if (!(in.obs2_deg < 0.0)) r.obs2_rad = within("tune", "obs2_deg", in.obs2_deg, 0.0, 360.0) * units::kDegToRad;
  if (r.nav1_khz == 0 && r.nav2_khz == 0 && r.adf_khz == 0) {
    throw RequestError("tune: give nav1_mhz, nav2_mhz or adf_khz");
  }
  return r;
}

TimeOfDayRequest make_request(const TimeOfDayInput& in) {
  const std::optional<UtcTime> utc = parse_utc(in.utc);
  if (!utc) {
    throw RequestError("time of day: utc: '" + in.utc + "': expected YYYY-MM-DDTHH:MM:SS (UTC, a real date, years " +
                       std::to_string(kFirstYear) + "-" + std::to_string(kLastYear) + ")");
  }
  return {*utc, in.lights};
}

FailureRequest make_failure(const std::string& system, bool active) {
  if (!failure_target_owner(system)) {
    // Refused here: no federate would act on it, and nothing would say so.
    throw RequestError("failure: unknown system '" + system + "'; one of: " + failure_targets_description());
  }
  return {system, active};
}

SnapshotRequest make_snapshot(const std::string& channel, const std::string& tag) {
  if (tag.size() > 48 || !only_chars(tag, kTagChars)) {
    throw RequestError("snapshot: tag: '" + tag + "': up to 48 characters of [A-Za-z0-9_-]");
  }
  checked_target("snapshot", channel);
  return {channel, tag};
}

std::string describe(const InstructorRequest& request) {
  struct Describe {
    std::string operator()(const RunStateRequest& r) const {
      return r.state == RunState::kRun ? "run" : r.state == RunState::kFreeze ? "freeze" : "reset";
    }
    std::string operator()(const RepositionRequest& r) const {
      char buf[160];
      switch (r.kind) {
        case RepositionRequest::Kind::kRunwayThreshold:
          return "reposition to " + r.airport + " " + r.runway + " threshold";
        case RepositionRequest::Kind::kApproachGate:
          std::snprintf(buf, sizeof buf, "reposition to %s %s gate %.1f NM", r.airport.c_str(),
                        r.runway.c_str(), r.gate_distance_m / units::kNmToM);
          return buf;
        case RepositionRequest::Kind::kPoint:
          std::snprintf(buf, sizeof buf, "reposition to %.5f %.5f %.0f ft heading %.0f",
                        r.latitude_rad * units::kRadToDeg, r.longitude_rad * units::kRadToDeg,
                        r.altitude_msl_m / units::kFtToM, r.heading_rad * units::kRadToDeg);
          return buf;
      }
      return "reposition";
    }
    std::string operator()(const WeatherRequest& w) const {
      char buf[200];
      std::snprintf(buf, sizeof buf, "weather: wind %03.0f/%.0f kt, turbulence %d, visibility %.0f m, cloud base %.0f ft",
                    w.wind_from_rad * units::kRadToDeg, w.wind_speed_mps / units::kKtToMps,
                    w.turbulence_intensity, w.visibility_m, w.cloud_base_m / units::kFtToM);
      return buf;
    }
    std::string operator()(const FailureRequest& f) const {
      return (f.active ? "fail " : "restore ") + f.system;
    }
    std::string operator()(const TimeOfDayRequest& t) const {
      char buf[80];
      const int s = static_cast<int>(t.utc.seconds_of_day);
      std::snprintf(buf, sizeof buf, "time of day %04d-%02d-%02dT%02d:%02d:%02dZ, lights %s", t.utc.year,
                    t.utc.month, t.utc.day, s / 3600, s / 60 % 60, s % 60, t.airport_lights_on ? "on" : "off");
      return buf;
    }
    std::string operator()(const RadioTuningRequest& r) const {
      std::string text = "tune";
      if (r.nav1_khz) text += " NAV1 " + number_text(r.nav1_khz / 1000.0);
      if (r.nav2_khz) text += " NAV2 " + number_text(r.nav2_khz / 1000.0);
      if (r.adf_khz) text += " ADF " + std::to_string(r.adf_khz);
      return text;
    }
    std::string operator()(const SnapshotRequest& s) const {
      return "snapshot" + (s.channel.empty() ? std::string() : " " + s.channel);
    }
    std::string operator()(const ShutdownRequest&) const { return "shutdown"; }
  };
  return std::visit(Describe{}, request);
}

}  // namespace fedsim::instructor
