// Instructor commands as values: each field checked and converted once, whoever typed it.
#include "common/instructor/instructor_request.hpp"
#include "common/instructor/request_json.hpp"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <cmath>
#include <limits>

namespace fedsim::instructor {
namespace {

constexpr double kDeg = 3.14159265358979323846 / 180.0;

std::string error_of(const std::string& json_text) {
  try {
    request_from_json_text(json_text);
  } catch (const RequestError& e) {
    return e.what();
  }
  return "(accepted)";
}

TEST(InstructorRequest, RunStatesByWord) {
  EXPECT_EQ(std::get<RunStateRequest>(request_from_json_text(R"({"command":"freeze"})")).state, RunState::kFreeze);
  EXPECT_EQ(std::get<RunStateRequest>(request_from_json_text(R"({"command":"run"})")).state, RunState::kRun);
  EXPECT_EQ(std::get<RunStateRequest>(request_from_json_text(R"({"command":"reset"})")).state, RunState::kReset);
  EXPECT_NE(error_of(R"({"command":"freeze","now":true})").find("unknown field 'now'"), std::string::npos);
}

TEST(InstructorRequest, RepositionToAGateConvertsNauticalMiles) {
  const auto r = std::get<RepositionRequest>(
      request_from_json_text(R"({"command":"reposition","airport":"KSFO","runway":"28R","gate_nm":10})"));
  EXPECT_EQ(r.kind, RepositionRequest::Kind::kApproachGate);
  EXPECT_DOUBLE_EQ(r.gate_distance_m, 18520.0);
  EXPECT_EQ(describe(r), "reposition to KSFO 28R gate 10.0 NM");
  // No gate: the threshold.
  const auto t = std::get<RepositionRequest>(
      request_from_json_text(R"({"command":"reposition","airport":"KSFO","runway":"28R"})"));
  EXPECT_EQ(t.kind, RepositionRequest::Kind::kRunwayThreshold);
}

TEST(InstructorRequest, RepositionToAPointInSi) {
  const auto r = std::get<RepositionRequest>(request_from_json_text(
      R"({"command":"reposition","lat_deg":37.5,"lon_deg":-122.25,"alt_ft":3000,"heading_deg":-80,"kt":140})"));
  EXPECT_EQ(r.kind, RepositionRequest::Kind::kPoint);
  EXPECT_DOUBLE_EQ(r.latitude_rad, 37.5 * kDeg);
  EXPECT_DOUBLE_EQ(r.longitude_rad, -122.25 * kDeg);
  EXPECT_DOUBLE_EQ(r.altitude_msl_m, 914.4);
  EXPECT_NEAR(r.heading_rad, 280.0 * kDeg, 1e-12);  // carried in [0, 2 pi)
  EXPECT_NEAR(r.airspeed_mps, 140.0 * 1852.0 / 3600.0, 1e-12);
}

TEST(InstructorRequest, EveryBadNumberIsRefusedByName) {
  EXPECT_NE(error_of(R"({"command":"reposition","lat_deg":95,"lon_deg":0,"alt_ft":0,"heading_deg":0})")
                .find("lat_deg: 95 is outside -90..90"), std::string::npos);
  EXPECT_NE(error_of(R"({"command":"reposition","lat_deg":1,"lon_deg":0,"alt_ft":0})").find("needs heading_deg"),
            std::string::npos);
  EXPECT_NE(error_of(R"({"command":"reposition","lat_deg":1,"lon_deg":0,"alt_ft":"high","heading_deg":0})")
                .find("alt_ft: \"high\" is not a number"), std::string::npos);
  EXPECT_NE(error_of(R"({"command":"reposition","airport":"KSFO","runway":"28R","gate_nm":31})").find("gate_nm"),
            std::string::npos);
  EXPECT_NE(error_of(R"({"command":"reposition","airport":"../x","runway":"28R"})").find("airport"), std::string::npos);
  EXPECT_NE(error_of(R"({"command":"weather","wind_kt":-5})").find("wind_kt: -5 is outside"), std::string::npos);
  EXPECT_NE(error_of(R"({"command":"weather","turbulence":"extreme"})").find("turbulence"), std::string::npos);
  EXPECT_NE(error_of(R"({"command":"weather","seed":1.5})").find("seed"), std::string::npos);
  EXPECT_NE(error_of(R"({"command":"weather","qnh_hpa":500})").find("qnh_hpa"), std::string::npos);
  EXPECT_NE(error_of(R"({"command":"weather","visibility_m":0})").find("visibility_m"), std::string::npos);
  EXPECT_NE(error_of(R"({"command":"tune","nav1_mhz":120})").find("nav1_mhz"), std::string::npos);
  EXPECT_NE(error_of(R"({"command":"tune"})").find("give nav1_mhz"), std::string::npos);
  EXPECT_NE(error_of(R"({"command":"fail","system":"enigne1"})").find("unknown system 'enigne1'"), std::string::npos);
  EXPECT_NE(error_of(R"({"command":"fail"})").find("which system"), std::string::npos);
  EXPECT_NE(error_of(R"({"command":"time_of_day","utc":"2026-02-30T10:00:00"})").find("utc"), std::string::npos);
  EXPECT_NE(error_of(R"({"command":"snapshot","tag":"../../etc"})").find("tag"), std::string::npos);
  EXPECT_NE(error_of(R"({"command":"launch"})").find("unknown command 'launch'"), std::string::npos);
  EXPECT_NE(error_of(R"([1,2])").find("JSON object"), std::string::npos);
  EXPECT_NE(error_of(R"({"command":)").find("not JSON"), std::string::npos);
  // The edge forms refuse what JSON cannot carry but a command line can.
  RepositionInput nan_point;
  nan_point.point = true;
  nan_point.lat_deg = std::numeric_limits<double>::quiet_NaN();
  EXPECT_THROW(make_request(nan_point), RequestError);
  WeatherInput inf_wind;
  inf_wind.wind_kt = std::numeric_limits<double>::infinity();
  EXPECT_THROW(make_request(inf_wind), RequestError);
}

TEST(InstructorRequest, WeatherInSi) {
  const auto w = std::get<WeatherRequest>(request_from_json_text(
      R"({"command":"weather","wind_from_deg":280,"wind_kt":20,"gradient_kt_per_1000ft":3,"turbulence":"moderate",
          "seed":42,"isa_dev_k":-5,"qnh_hpa":1003.5,"visibility_m":800,"cloud_base_ft":1000})"));
  EXPECT_NEAR(w.wind_from_rad, 280.0 * kDeg, 1e-12);
  EXPECT_NEAR(w.wind_speed_mps, 20.0 * 1852.0 / 3600.0, 1e-12);
  EXPECT_NEAR(w.wind_gradient_mps_per_m, 3.0 * 1852.0 / 3600.0 / 304.8, 1e-12);
  EXPECT_EQ(w.turbulence_intensity, 2);
  EXPECT_EQ(w.turbulence_seed, 42u);
  EXPECT_DOUBLE_EQ(w.sea_level_pressure_pa, 100350.0);
  EXPECT_DOUBLE_EQ(w.visibility_m, 800.0);
  EXPECT_DOUBLE_EQ(w.cloud_base_m, 304.8);
  // Nothing given: calm standard day (QNH 0 = standard).
  const auto calm = std::get<WeatherRequest>(request_from_json_text(R"({"command":"weather"})"));
  EXPECT_EQ(calm.wind_speed_mps, 0.0);
  EXPECT_EQ(calm.sea_level_pressure_pa, 0.0);
}

TEST(InstructorRequest, TuningDialsTheFiftyKilohertzChannel) {
  const auto r = std::get<RadioTuningRequest>(
      request_from_json_text(R"({"command":"tune","nav1_mhz":111.7,"obs1_deg":284,"adf_khz":362})"));
  EXPECT_EQ(r.nav1_khz, 111700u);
  EXPECT_EQ(r.nav2_khz, 0u);  // left as it is
  EXPECT_NEAR(r.obs1_rad, 284.0 * kDeg, 1e-12);
  EXPECT_LT(r.obs2_rad, 0.0);
  EXPECT_EQ(r.adf_khz, 362u);
}

TEST(InstructorRequest, FailureRestoreAndTimeOfDay) {
  const auto f = std::get<FailureRequest>(request_from_json_text(R"({"command":"restore","system":"nav1"})"));
  EXPECT_EQ(f.system, "nav1");
  EXPECT_FALSE(f.active);
  const auto t = std::get<TimeOfDayRequest>(
      request_from_json_text(R"({"command":"time_of_day","utc":"2028-02-29T01:30:15","lights":false})"));
  EXPECT_EQ(t.utc.year, 2028);
  EXPECT_EQ(t.utc.day, 29);  // a leap day
  EXPECT_DOUBLE_EQ(t.utc.seconds_of_day, 5415.0);
  EXPECT_FALSE(t.airport_lights_on);
  EXPECT_EQ(describe(t), "time of day 2028-02-29T01:30:15Z, lights off");
}

TEST(UtcTime, RealDatesOnly) {
  EXPECT_TRUE(parse_utc("2024-02-29T00:00:00"));
  EXPECT_FALSE(parse_utc("2023-02-29T00:00:00"));
  EXPECT_FALSE(parse_utc("1900-02-29T00:00:00"));  // a century, not a leap year
  EXPECT_TRUE(parse_utc("2000-02-29T00:00:00"));   // divisible by 400
  EXPECT_FALSE(parse_utc("2026-04-31T00:00:00"));
  EXPECT_FALSE(parse_utc("2026-12-22T24:00:00"));
  EXPECT_FALSE(parse_utc("2026-12-22T-1:00:00"));
  EXPECT_FALSE(parse_utc("2301-01-01T00:00:00"));
  EXPECT_FALSE(parse_utc("2026-12-22T01:30:00Z"));  // trailing text
  EXPECT_EQ(days_in_month(2026, 13), 0);
}

}  // namespace
}  // namespace fedsim::instructor
