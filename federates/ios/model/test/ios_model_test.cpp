// The station's pure parts: who may use it, the field registry, command confirmation from what
// the federation reports, and the map around an airport.
#include "ios/model/access_policy.hpp"
#include "common/util/build_paths.hpp"
#include "ios/model/command_tracker.hpp"
#include "ios/model/live_fields.hpp"
#include "ios/model/map_layers.hpp"

#include "common/instructor/request_json.hpp"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <cmath>

namespace fedsim::ios {
namespace {

constexpr double kDeg = 3.14159265358979323846 / 180.0;

TEST(AccessPolicy, LoopbackIsServedAnyOtherAddressNeedsTheToken) {
  for (const char* a : {"127.0.0.1", "127.3.2.1", "::1", "::ffff:127.0.0.1"}) EXPECT_TRUE(is_loopback_address(a)) << a;
  for (const char* a : {"10.0.0.1", "192.168.1.2", "::ffff:10.0.0.1", "fe80::1", "0.0.0.0", "localhost", ""}) {
    EXPECT_FALSE(is_loopback_address(a)) << a;
  }
  const std::string token = "0123456789abcdef";
  EXPECT_TRUE(request_allowed("127.0.0.1", "", ""));
  EXPECT_FALSE(request_allowed("10.1.2.3", "", ""));           // no token configured: loopback only
  EXPECT_FALSE(request_allowed("10.1.2.3", "", token));
  EXPECT_FALSE(request_allowed("10.1.2.3", "0123456789abcdeX", token));
  EXPECT_TRUE(request_allowed("10.1.2.3", token, token));
  EXPECT_EQ(presented_token("Bearer abc", "token=zzz", ""), "abc");
  EXPECT_EQ(presented_token("", "a=1&token=zzz", ""), "zzz");
  EXPECT_EQ(presented_token("", "", "x=1; fedsim_token=ccc"), "ccc");
  EXPECT_EQ(presented_token("Basic abc", "tokens=1", "token=2"), "");
}

TEST(AccessPolicy, ABindBeyondTheLoopbackNeedsAToken) {
  EXPECT_EQ(bind_problem("127.0.0.1", ""), "");
  EXPECT_NE(bind_problem("0.0.0.0", "").find("give an access token"), std::string::npos);
  EXPECT_NE(bind_problem("0.0.0.0", "short").find("at least 16"), std::string::npos);
  EXPECT_EQ(bind_problem("0.0.0.0", "0123456789abcdef"), "");
  EXPECT_NE(bind_problem("my-host", "").find("not an IPv4 or IPv6 address"), std::string::npos);
}

TEST(LiveFields, NumbersByRecorderNameTextApart) {
  LiveFields f;
  f.update("fedsim/aircraft_state", {"stamp.frame", "altitude_msl_m", "stalled", "air.wind_ned_mps[0]", "ident", "seq"},
           {"12", "1219.2", "0", "nan", "\"SFO, CA\"", "[1,2]"}, 3.0);
  EXPECT_EQ(f.value("fedsim/aircraft_state", "altitude_msl_m"), 1219.2);
  EXPECT_EQ(f.value("fedsim/aircraft_state", "stalled"), 0.0);
  EXPECT_TRUE(std::isnan(*f.value("fedsim/aircraft_state", "air.wind_ned_mps[0]")));
  EXPECT_FALSE(f.value("fedsim/aircraft_state", "ident"));  // text, not a number
  EXPECT_FALSE(f.value("fedsim/aircraft_state", "nothing"));
  EXPECT_FALSE(f.value("fedsim/other", "altitude_msl_m"));
  const auto j = nlohmann::json::parse(f.to_json());
  EXPECT_EQ(j["fedsim/aircraft_state"]["f"]["altitude_msl_m"], 1219.2);
  EXPECT_TRUE(j["fedsim/aircraft_state"]["f"]["air.wind_ned_mps[0]"].is_null());  // JSON has no NaN
  EXPECT_EQ(j["fedsim/aircraft_state"]["t"]["ident"], "SFO, CA");
  EXPECT_FALSE(j["fedsim/aircraft_state"]["t"].contains("seq"));
  EXPECT_EQ(instance_name("fedsim/engine_state", {"aircraft_id", "engine_index"}, {"0", "1"}), "fedsim/engine_state[1]");
  EXPECT_EQ(instance_name("fedsim/aircraft_state", {"aircraft_id"}, {"0"}), "fedsim/aircraft_state");
}

/// A federation as the tracker sees it: fields set by the test.
struct Observed {
  LiveFields fields;
  FieldLookup lookup() {
    return [this](const std::string& t, const std::string& f) { return fields.value(t, f); };
  }
};

TEST(CommandTracker, FreezeIsConfirmedByTheTickNotBySending) {
  Observed seen;
  seen.fields.set("timing", "run_state", 0, 0.0);  // running
  CommandTracker tracker(5.0);
  tracker.sent(1, instructor::request_from_json_text(R"({"command":"freeze"})"), 10.0, seen.lookup());
  EXPECT_TRUE(tracker.update(10.1, seen.lookup()).empty());
  EXPECT_EQ(tracker.commands().front().status, CommandStatus::kPending);
  seen.fields.set("timing", "run_state", 1, 0.0);  // the timing federate froze
  const auto settled = tracker.update(10.2, seen.lookup());
  ASSERT_EQ(settled.size(), 1u);
  EXPECT_EQ(settled[0].status, CommandStatus::kConfirmed);
  EXPECT_NE(settled[0].evidence.find("run_state = 1"), std::string::npos);
}

TEST(CommandTracker, WhatNobodyReportsIsUnconfirmedAfterTheTimeout) {
  Observed seen;
  seen.fields.set("timing", "run_state", 0, 0.0);
  CommandTracker tracker(5.0);
  tracker.sent(1, instructor::request_from_json_text(R"({"command":"freeze"})"), 0.0, seen.lookup());
  EXPECT_TRUE(tracker.update(4.9, seen.lookup()).empty());
  const auto settled = tracker.update(5.1, seen.lookup());
  ASSERT_EQ(settled.size(), 1u);
  EXPECT_EQ(settled[0].status, CommandStatus::kUnconfirmed);
}

TEST(CommandTracker, RepositionIsConfirmedWhereTheAircraftIs) {
  Observed seen;
  seen.fields.set("fedsim/aircraft_state", "latitude_rad", 37.0 * kDeg, 0.0);
  seen.fields.set("fedsim/aircraft_state", "longitude_rad", -122.0 * kDeg, 0.0);
  CommandTracker tracker(5.0);
  tracker.sent(7, instructor::request_from_json_text(
                      R"({"command":"reposition","lat_deg":37.5,"lon_deg":-122.25,"alt_ft":3000,"heading_deg":280})"),
               0.0, seen.lookup());
  EXPECT_TRUE(tracker.update(0.1, seen.lookup()).empty());  // still 58 km away
  seen.fields.set("fedsim/aircraft_state", "latitude_rad", 37.5 * kDeg + 1e-6, 0.0);
  seen.fields.set("fedsim/aircraft_state", "longitude_rad", -122.25 * kDeg, 0.0);
  const auto settled = tracker.update(0.2, seen.lookup());
  ASSERT_EQ(settled.size(), 1u);
  EXPECT_EQ(settled[0].status, CommandStatus::kConfirmed);
  EXPECT_NE(settled[0].evidence.find("6 m from the place sent"), std::string::npos) << settled[0].evidence;
}

TEST(CommandTracker, AFailureIsConfirmedByItsOwnersReport) {
  Observed seen;
  seen.fields.set("fedsim/engine_state[0]", "failed", 0, 0.0);
  seen.fields.set("fedsim/engine_state[1]", "failed", 0, 0.0);
  CommandTracker tracker(5.0);
  tracker.sent(1, instructor::request_from_json_text(R"({"command":"fail","system":"engine2"})"), 0.0, seen.lookup());
  seen.fields.set("fedsim/engine_state[0]", "failed", 1, 0.0);  // the wrong engine: not evidence
  EXPECT_TRUE(tracker.update(0.1, seen.lookup()).empty());
  seen.fields.set("fedsim/engine_state[1]", "failed", 1, 0.0);
  ASSERT_EQ(tracker.update(0.2, seen.lookup()).size(), 1u);
  // A station failure has no report to read: shown as sent, never as confirmed.
  tracker.sent(2, instructor::request_from_json_text(R"({"command":"fail","system":"station:SFO"})"), 1.0, seen.lookup());
  EXPECT_EQ(tracker.commands().front().status, CommandStatus::kSent);
}

TEST(CommandTracker, WeatherIsConfirmedByTheWindAtTheAircraft) {
  Observed seen;
  seen.fields.set("fedsim/aircraft_state", "air.wind_ned_mps[0]", 0, 0.0);
  seen.fields.set("fedsim/aircraft_state", "air.wind_ned_mps[1]", 0, 0.0);
  seen.fields.set("fedsim/aircraft_state", "height_agl_m", 1000, 0.0);
  CommandTracker tracker(5.0);
  tracker.sent(1, instructor::request_from_json_text(R"({"command":"weather","wind_from_deg":270,"wind_kt":20})"), 0.0,
               seen.lookup());
  EXPECT_TRUE(tracker.update(0.1, seen.lookup()).empty());  // calm: not yet
  seen.fields.set("fedsim/aircraft_state", "air.wind_ned_mps[1]", 10.3, 0.0);  // 20 kt blowing east
  ASSERT_EQ(tracker.update(0.2, seen.lookup()).size(), 1u);
}

#ifdef fedsim::util::navdb_file()
TEST(MapLayers, KsfoRunwaysIlsAndNavaids) {
  const auto db = nav::NavDatabase::open(fedsim::util::navdb_file());
  const auto map = nlohmann::json::parse(map_json(db, "KSFO", 20));
  EXPECT_EQ(map["runways"].size(), 8u);  // 01L/R, 19L/R, 10L/R, 28L/R
  EXPECT_EQ(map["ils"].size(), 2u);      // 28L, 28R in the ILS table
  bool sfo = false;
  for (const auto& n : map["navaids"]) {
    sfo |= n["ident"] == "SFO";
    EXPECT_LE(n["distance_nm"].get<double>(), 20.0);
  }
  EXPECT_TRUE(sfo);
  EXPECT_NEAR(map["center"]["lat_deg"].get<double>(), 37.62, 0.02);
  EXPECT_THROW(map_json(db, "XXXX", 20), std::invalid_argument);
  EXPECT_THROW(map_json(db, "KSFO", 0), std::invalid_argument);
  // A 10 NM gate lies 10 NM from the threshold, along the approach course.
  const auto gate = expected_position(db, "KSFO", "28R", 18520.0);
  const auto threshold = expected_position(db, "KSFO", "28R", 0.0);
  ASSERT_TRUE(gate && threshold);
  const double dlat = (gate->latitude_rad - threshold->latitude_rad) * 6371000.0;
  const double dlon = (gate->longitude_rad - threshold->longitude_rad) * 6371000.0 * std::cos(threshold->latitude_rad);
  EXPECT_NEAR(std::hypot(dlat, dlon), 18520.0, 60.0);
  EXPECT_GT(dlon, 0.0);  // 28R lands west: the gate is east of the threshold
  EXPECT_FALSE(expected_position(db, "KSFO", "99", 0.0));
}
#endif

}  // namespace
}  // namespace fedsim::ios
