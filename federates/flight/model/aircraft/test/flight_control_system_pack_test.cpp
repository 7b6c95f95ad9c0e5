// The packs' flight control system: the 737's yaw damper (from JSBSim's <flight_control>) and
// stabiliser trim, the C172's trim tab, and the loader's checks of both sections.
#include <gtest/gtest.h>
#include "common/util/build_paths.hpp"

#include <fstream>
#include <sstream>
#include <string>

#include "common/util/config_node.hpp"
#include "flight/model/aircraft/aircraft_pack.hpp"

namespace fedsim::flight {
namespace {

std::string pack_text(const std::string& name) {
  std::ifstream in(fedsim::util::data_dir() + "/aircraft/" + name);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

std::string replaced(std::string text, const std::string& from, const std::string& to) {
  const auto at = text.find(from);
  EXPECT_NE(at, std::string::npos) << from;
  if (at != std::string::npos) text.replace(at, from.size(), to);
  return text;
}

TEST(FlightControlSystemPack, The737HasItsJsbsimYawDamperAndAStabiliserTrim) {
  const AircraftPack p = load_aircraft_pack(fedsim::util::data_dir() + "/aircraft/b737.yaml");
  ASSERT_TRUE(p.flight_controls.yaw_damper);
  const YawDamperSpec& yd = *p.flight_controls.yaw_damper;
  // 737.xml: rudder-sum += r-aero-rad_sec x table(Mach: 0 to 0.10 -> 0, 0.11 -> 1), twice;
  // fedsim's rudder +1 is JSBSim's -1: -1 per rad/s, i.e. left rudder for a yaw to the right.
  EXPECT_DOUBLE_EQ(yd.gain_per_radps(0.05), 0.0);
  EXPECT_DOUBLE_EQ(yd.gain_per_radps(0.3), -1.0);
  EXPECT_EQ(yd.washout_time_constant_s, 0.0);
  EXPECT_TRUE(yd.engaged_at_start);
  ASSERT_TRUE(p.flight_controls.pitch_trim);
  EXPECT_EQ(p.flight_controls.pitch_trim->kind, PitchTrimKind::kStabiliser);
  EXPECT_GT(p.flight_controls.pitch_trim->rate_per_s, 0.0);
}

TEST(FlightControlSystemPack, TheC172HasATrimTabAndNoYawDamper) {
  const AircraftPack p = load_aircraft_pack(fedsim::util::data_dir() + "/aircraft/c172.yaml");
  EXPECT_FALSE(p.flight_controls.yaw_damper);
  ASSERT_TRUE(p.flight_controls.pitch_trim);
  EXPECT_EQ(p.flight_controls.pitch_trim->kind, PitchTrimKind::kTab);
}

TEST(FlightControlSystemPack, TheC172HasItsJsbsimWingLeveller) {
  const AircraftPack p = load_aircraft_pack(fedsim::util::data_dir() + "/aircraft/c172.yaml");
  ASSERT_TRUE(p.flight_controls.wing_leveller);
  const WingLevellerSpec& w = *p.flight_controls.wing_leveller;
  // c172ap.xml: ap/roll-pid-kp 50, -ki 5, -kd 17; the output switch passes -PID.
  EXPECT_DOUBLE_EQ(w.bank_gain_per_rad, 50.0);
  EXPECT_DOUBLE_EQ(w.bank_integral_gain_per_rad_s, 5.0);
  EXPECT_DOUBLE_EQ(w.bank_rate_gain_per_radps, 17.0);
  EXPECT_TRUE(w.airborne_only);       // the selector tests gear WOW == 0
  EXPECT_FALSE(w.engaged_at_start);   // the pilot's switch engages it
  EXPECT_FALSE(load_aircraft_pack(fedsim::util::data_dir() + "/aircraft/b737.yaml")
                   .flight_controls.wing_leveller);
}

void expect_error(const std::string& text, const std::string& field, const std::string& words) {
  try {
    parse_aircraft_pack(text, "b737-variant.yaml");
    ADD_FAILURE() << "accepted: " << field;
  } catch (const util::ConfigError& e) {
    const std::string message = e.what();
    EXPECT_NE(message.find(field), std::string::npos) << message;
    EXPECT_NE(message.find(words), std::string::npos) << message;
  }
}

TEST(FlightControlSystemPack, BadSectionsFailAtTheirField) {
  const std::string b737 = pack_text("b737.yaml");
  expect_error(replaced(b737, "kind: stabiliser", "kind: canard"), "flight_controls.pitch_trim.kind", "stabiliser");
  expect_error(replaced(b737, "rate_per_s: 0.03", "rate_per_s: 0"), "flight_controls.pitch_trim", "positive");
  expect_error(replaced(b737, "rate_per_s: 0.03", "rate_per_s: 0.03\n    speed: 2"), "flight_controls.pitch_trim",
               "speed");
  expect_error(replaced(b737, "      row: mach\n      row_breakpoints: [0.0, 0.1, 0.11]",
                        "      row: alpha_rad\n      row_breakpoints: [0.0, 0.1, 0.11]"),
               "flight_controls.yaw_damper.gain_per_radps", "mach");
  expect_error(replaced(b737, "engaged_at_start: true", "engaged_at_start: true\n    authority: 0"),
               "flight_controls.yaw_damper", "positive");
  const std::string leveller =
      "  wing_leveller:\n    bank_gain_per_rad: 50\n    bank_rate_gain_per_radps: 17\n";
  const std::string with_leveller = replaced(b737, "  pitch_trim:\n", leveller + "  pitch_trim:\n");
  EXPECT_TRUE(parse_aircraft_pack(with_leveller, "b737-variant.yaml").flight_controls.wing_leveller);
  expect_error(replaced(with_leveller, "bank_gain_per_rad: 50", "bank_gain_per_rad: .nan"),
               "flight_controls.wing_leveller.bank_gain_per_rad", "");
  expect_error(replaced(with_leveller, "bank_rate_gain_per_radps: 17", "bank_rate_gain_per_radps: 1e6"),
               "flight_controls.wing_leveller.bank_rate_gain_per_radps", "");
  expect_error(replaced(with_leveller, "bank_gain_per_rad: 50\n", ""),
               "flight_controls.wing_leveller", "bank_gain_per_rad");
  expect_error(replaced(with_leveller, "bank_gain_per_rad: 50", "bank_gain_per_rad: 50\n    roll_gain: 2"),
               "flight_controls.wing_leveller", "roll_gain");
  // Negative control: the unmodified text loads.
  EXPECT_NO_THROW(parse_aircraft_pack(b737, "b737.yaml"));
}

}  // namespace
}  // namespace fedsim::flight
