#include "common/instructor/request_json.hpp"

#include <nlohmann/json.hpp>

#include <initializer_list>
#include <set>

namespace fedsim::instructor {

namespace {

using nlohmann::json;

/// Refuses keys other than "command" and `allowed`.
void only_keys(const json& body, const std::string& command, std::initializer_list<const char*> allowed) {
  std::set<std::string> keys{"command"};
  for (const char* k : allowed) keys.insert(k);
  for (const auto& [key, value] : body.items()) {
    if (!keys.count(key)) {
      std::string list;
      for (const char* k : allowed) list += std::string(list.empty() ? "" : ", ") + k;
      throw RequestError(command + ": unknown field '" + key + "'" +
                         (list.empty() ? std::string(" (it takes none)") : " (it takes " + list + ")"));
    }
  }
}

double number(const json& body, const std::string& command, const char* key, double fallback) {
  if (!body.contains(key)) return fallback;
  const json& v = body.at(key);
  if (!v.is_number()) throw RequestError(command + ": " + key + ": " + v.dump() + " is not a number");
  return v.get<double>();
}

std::string text(const json& body, const std::string& command, const char* key, const std::string& fallback = {}) {
  if (!body.contains(key)) return fallback;
  const json& v = body.at(key);
  if (!v.is_string()) throw RequestError(command + ": " + key + ": " + v.dump() + " is not a string");
  return v.get<std::string>();
}

bool boolean(const json& body, const std::string& command, const char* key, bool fallback) {
  if (!body.contains(key)) return fallback;
  const json& v = body.at(key);
  if (!v.is_boolean()) throw RequestError(command + ": " + key + ": " + v.dump() + " is not true or false");
  return v.get<bool>();
}

InstructorRequest reposition(const json& body) {
  const std::string c = "reposition";
  only_keys(body, c, {"target", "airport", "runway", "gate_nm", "lat_deg", "lon_deg", "alt_ft", "heading_deg", "kt"});
  RepositionInput in;
  in.target = text(body, c, "target");
  in.kt = number(body, c, "kt", 0.0);
  in.point = body.contains("lat_deg") || body.contains("lon_deg");
  if (in.point) {
    for (const char* k : {"lat_deg", "lon_deg", "alt_ft", "heading_deg"}) {
      if (!body.contains(k)) throw RequestError("reposition: a point needs " + std::string(k));
    }
    if (body.contains("airport") || body.contains("runway")) {
      throw RequestError("reposition: give a point or a runway, not both");
    }
    in.lat_deg = number(body, c, "lat_deg", 0.0);
    in.lon_deg = number(body, c, "lon_deg", 0.0);
    in.alt_ft = number(body, c, "alt_ft", 0.0);
    in.heading_deg = number(body, c, "heading_deg", 0.0);
  } else {
    in.airport = text(body, c, "airport");
    in.runway = text(body, c, "runway");
    in.gate_nm = number(body, c, "gate_nm", 0.0);
  }
  return make_request(in);
}

InstructorRequest weather(const json& body) {
  const std::string c = "weather";
  only_keys(body, c, {"wind_from_deg", "wind_kt", "gradient_kt_per_1000ft", "turbulence", "seed",
                      "isa_dev_k", "qnh_hpa", "visibility_m", "cloud_base_ft"});
  WeatherInput in;
  in.wind_from_deg = number(body, c, "wind_from_deg", in.wind_from_deg);
  in.wind_kt = number(body, c, "wind_kt", in.wind_kt);
  in.gradient_kt_per_1000ft = number(body, c, "gradient_kt_per_1000ft", in.gradient_kt_per_1000ft);
  in.turbulence = text(body, c, "turbulence", in.turbulence);
  in.seed = number(body, c, "seed", in.seed);
  in.isa_dev_k = number(body, c, "isa_dev_k", in.isa_dev_k);
  in.qnh_hpa = number(body, c, "qnh_hpa", in.qnh_hpa);
  in.visibility_m = number(body, c, "visibility_m", in.visibility_m);
  in.cloud_base_ft = number(body, c, "cloud_base_ft", in.cloud_base_ft);
  return make_request(in);
}

InstructorRequest tune(const json& body) {
  const std::string c = "tune";
  only_keys(body, c, {"target", "nav1_mhz", "nav2_mhz", "obs1_deg", "obs2_deg", "adf_khz"});
  TuningInput in;
  in.target = text(body, c, "target");
  in.nav1_mhz = number(body, c, "nav1_mhz", 0.0);
  in.nav2_mhz = number(body, c, "nav2_mhz", 0.0);
  in.obs1_deg = number(body, c, "obs1_deg", -1.0);
  in.obs2_deg = number(body, c, "obs2_deg", -1.0);
  in.adf_khz = number(body, c, "adf_khz", 0.0);
  return make_request(in);
}

}  // namespace

InstructorRequest request_from_json(const json& body) {
  if (!body.is_object()) throw RequestError("a command is a JSON object, not " + body.dump());
  if (!body.contains("command") || !body.at("command").is_string()) {
    throw RequestError("a command needs \"command\": run, freeze, reset, reposition, weather, fail, "
                       "restore, time_of_day, tune or snapshot");
  }
  const std::string command = body.at("command").get<std::string>();
  if (command == "run" || command == "freeze" || command == "reset") {
    only_keys(body, command, {});
    return make_run_state(command);
  }
  if (command == "reposition") return reposition(body);
  if (command == "weather") return weather(body);
  if (command == "tune") return tune(body);
  if (command == "fail" || command == "restore") {
    only_keys(body, command, {"system"});
    if (!body.contains("system")) throw RequestError(command + ": which system? (\"system\": \"engine1\")");
    return make_failure(text(body, command, "system"), command == "fail");
  }
  if (command == "time_of_day") {
    only_keys(body, command, {"utc", "lights"});
    return make_request(TimeOfDayInput{text(body, command, "utc"), boolean(body, command, "lights", true)});
  }
  if (command == "snapshot") {
    only_keys(body, command, {"channel", "tag"});
    return make_snapshot(text(body, command, "channel"), text(body, command, "tag"));
  }
  throw RequestError("unknown command '" + command + "' (run, freeze, reset, reposition, weather, fail, "
                     "restore, time_of_day, tune, snapshot)");
}

InstructorRequest request_from_json_text(const std::string& body_text) {
  json body;
  try {
    body = json::parse(body_text);
  } catch (const json::parse_error& e) {
    throw RequestError(std::string("the command is not JSON: ") + e.what());
  }
  return request_from_json(body);
}

}  // namespace fedsim::instructor
