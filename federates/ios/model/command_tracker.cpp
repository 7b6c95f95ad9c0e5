#include "ios/model/command_tracker.hpp"

#include <GeographicLib/Geodesic.hpp>

#include <cmath>

namespace fedsim::ios {

namespace {

using namespace instructor;

constexpr const char* kAircraft = "fedsim/aircraft_state";
constexpr const char* kNavigation = "fedsim/navigation_state";
constexpr const char* kTiming = "timing";  // the station's own view of the frame tick

// Enum values as the IDL numbers them (fedsim_common.idl, navigation.idl, motion.idl,
// autopilot.idl).
constexpr double kRunStateRun = 0, kRunStateFreeze = 1;
constexpr double kSignalReceiverFailed = 4;
constexpr double kMotionFault = 3;
constexpr double kControlLoadingSafe = 0;
constexpr std::uint32_t kAlertApFailed = 128, kAlertAtFailed = 256;

std::string number(double v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%g", v);
  return buf;
}

/// "field = value" when `field` of `topic` satisfies `holds`.
std::optional<std::string> when(const FieldLookup& lookup, const std::string& topic, const std::string& field,
                                const std::function<bool(double)>& holds) {
  const std::optional<double> v = lookup(topic, field);
  if (!v || !holds(*v)) return std::nullopt;
  return topic + " " + field + " = " + number(*v);
}

std::optional<std::string> failure_confirmation(const FailureRequest& f, const FieldLookup& lookup) {
  const bool on = f.active;
  const std::string& s = f.system;
  if (s.size() == 7 && s.compare(0, 6, "engine") == 0) {
    const std::string topic = "fedsim/engine_state[" + std::to_string(s[6] - '1') + "]";
    return when(lookup, topic, "failed", [on](double v) { return (v != 0.0) == on; });
  }
  if (s == "nav1" || s == "nav2") {
    const std::string field = std::string("nav[") + (s == "nav1" ? "0" : "1") + "].status";
    return when(lookup, kNavigation, field, [on](double v) { return (v == kSignalReceiverFailed) == on; });
  }
  if (s == "adf") {
    return when(lookup, kNavigation, "adf.status", [on](double v) { return (v == kSignalReceiverFailed) == on; });
  }
  if (s == "ins") return when(lookup, kNavigation, "ins.valid", [on](double v) { return (v == 0.0) == on; });
  if (s == "gps") return when(lookup, kNavigation, "gps.denied", [on](double v) { return (v != 0.0) == on; });
  if (s == "autopilot" || s == "autothrottle") {
    const std::uint32_t bit = s == "autopilot" ? kAlertApFailed : kAlertAtFailed;
    return when(lookup, "fedsim/autopilot_state", "fma.alerts",
                [on, bit](double v) { return ((static_cast<std::uint32_t>(v) & bit) != 0) == on; });
  }
  if (s == "motion") {
    return when(lookup, "fedsim/motion_state", "status", [on](double v) { return (v == kMotionFault) == on; });
  }
  if (s == "control_loading") {
    return when(lookup, "fedsim/control_loading_state", "status",
                [on](double v) { return (v == kControlLoadingSafe) == on; });
  }
  return std::nullopt;  // station failures: no per-station report to read
}

bool can_confirm(const InstructorRequest& r) {
  if (const auto* f = std::get_if<FailureRequest>(&r)) return f->system.compare(0, 7, "station") != 0;
  return std::holds_alternative<RunStateRequest>(r) || std::holds_alternative<RepositionRequest>(r) ||
         std::holds_alternative<WeatherRequest>(r) || std::holds_alternative<RadioTuningRequest>(r);
}

}  // namespace

const char* status_name(CommandStatus s) {
  switch (s) {
    case CommandStatus::kPending: return "pending";
    case CommandStatus::kConfirmed: return "confirmed";
    case CommandStatus::kUnconfirmed: return "unconfirmed";
    case CommandStatus::kSent: return "sent";
  }
  return "?";
}

CommandTracker::CommandTracker(double timeout_s, std::size_t keep) : timeout_s_(timeout_s), keep_(keep) {}

void CommandTracker::sent(std::uint32_t sequence, const InstructorRequest& request, double now_s,
                          const FieldLookup& lookup, std::optional<ExpectedPosition> expected) {
  TrackedCommand c;
  c.sequence = sequence;
  c.text = describe(request);
  c.sent_s = now_s;
  if (!can_confirm(request)) {
    c.status = CommandStatus::kSent;
    c.settled_s = now_s;
    c.evidence = "no federate reports it";
  }
  commands_.push_front(c);
  pending_.push_front(Pending{request, expected, lookup(kTiming, "sim_time_s")});
  while (commands_.size() > keep_) {
    commands_.pop_back();
    pending_.pop_back();
  }
}

std::optional<std::string> CommandTracker::confirmation(const Pending& p, const FieldLookup& lookup) const {
  if (const auto* r = std::get_if<RunStateRequest>(&p.request)) {
    if (r->state == RunState::kReset) {
      // A reset shows as sim time back near zero (it runs or freezes on from there).
      const double before = p.sim_time_at_send_s.value_or(0.0);
      return when(lookup, kTiming, "sim_time_s", [before](double t) { return t < before || t < 0.5; });
    }
    const double want = r->state == RunState::kRun ? kRunStateRun : kRunStateFreeze;
    return when(lookup, kTiming, "run_state", [want](double v) { return v == want; });
  }
  if (const auto* r = std::get_if<RepositionRequest>(&p.request)) {
    double lat = r->latitude_rad, lon = r->longitude_rad;
    if (r->kind != RepositionRequest::Kind::kPoint) {
      if (!p.expected) return std::nullopt;
      lat = p.expected->latitude_rad;
      lon = p.expected->longitude_rad;
    }
    const auto a_lat = lookup(kAircraft, "latitude_rad");
    const auto a_lon = lookup(kAircraft, "longitude_rad");
    if (!a_lat || !a_lon) return std::nullopt;
    constexpr double kToDeg = 180.0 / 3.14159265358979323846;
    double distance_m = 0.0;
    GeographicLib::Geodesic::WGS84().Inverse(lat * kToDeg, lon * kToDeg, *a_lat * kToDeg, *a_lon * kToDeg, distance_m);
    if (distance_m > 1000.0) return std::nullopt;
    return "aircraft " + number(std::round(distance_m)) + " m from the place sent";
  }
  if (const auto* w = std::get_if<WeatherRequest>(&p.request)) {
    const auto n = lookup(kAircraft, "air.wind_ned_mps[0]");
    const auto e = lookup(kAircraft, "air.wind_ned_mps[1]");
    const auto h = lookup(kAircraft, "height_agl_m");
    if (!n || !e || !h) return std::nullopt;
    const double asked = w->wind_speed_mps + w->wind_gradient_mps_per_m * std::max(0.0, *h);
    const double seen = std::hypot(*n, *e);
    if (std::abs(seen - asked) > std::max(3.0, 0.25 * asked)) return std::nullopt;
    return "wind at the aircraft " + number(std::round(seen * 10) / 10) + " m/s (asked " +
           number(std::round(asked * 10) / 10) + ")";
  }
  if (const auto* f = std::get_if<FailureRequest>(&p.request)) return failure_confirmation(*f, lookup);
  if (const auto* t = std::get_if<RadioTuningRequest>(&p.request)) {
    std::optional<std::string> seen;
    for (int i = 0; i < 2; ++i) {
      const std::uint32_t khz = i == 0 ? t->nav1_khz : t->nav2_khz;
      if (khz == 0) continue;
      seen = when(lookup, kNavigation, "nav[" + std::to_string(i) + "].frequency_khz",
                  [khz](double v) { return v == khz; });
      if (!seen) return std::nullopt;
    }
    if (t->adf_khz != 0) {
      seen = when(lookup, kNavigation, "adf.frequency_khz", [t](double v) { return std::abs(v - t->adf_khz) < 0.5; });
    }
    return seen;
  }
  return std::nullopt;
}

std::vector<TrackedCommand> CommandTracker::update(double now_s, const FieldLookup& lookup) {
  std::vector<TrackedCommand> settled;
  for (std::size_t i = 0; i < commands_.size(); ++i) {
    TrackedCommand& c = commands_[i];
    if (c.status != CommandStatus::kPending) continue;
    if (const auto evidence = confirmation(pending_[i], lookup)) {
      c.status = CommandStatus::kConfirmed;
      c.evidence = *evidence;
    } else if (now_s - c.sent_s > timeout_s_) {
      c.status = CommandStatus::kUnconfirmed;
      c.evidence = "no federate reported it within " + number(timeout_s_) + " s";
    } else {
      continue;
    }
    c.settled_s = now_s;
    settled.push_back(c);
  }
  return settled;
}

}  // namespace fedsim::ios
