// The facts other federates read from a pack without a flight model (common/aircraft_pack) are
// the flight model's own, to the last bit: the CG at the pack's loading and the pilot's eye from
// it (fedsim-visual's eye point), and the stall-warning schedule the pack states (the control
// loader's stick shaker), which the loader checks against the pack's lift. Negative controls: a
// pack stating a schedule its lift does not give is refused, naming the angle it should state;
// a different loading moves the CG in both alike.
#include "common/aircraft_pack/pack_facts.hpp"
#include "common/util/build_paths.hpp"
#include "common/util/config_node.hpp"
#include "flight/model/aircraft/aircraft_model.hpp"
#include "flight/model/aircraft/stall_warning.hpp"

#include <gtest/gtest.h>

#include <cstdio>
#include <fstream>
#include <sstream>
#include <string>

namespace fedsim::flight {
namespace {

std::string data_pack(const std::string& name) { return fedsim::util::data_dir() + "/aircraft/" + name; }

std::string text_of(const std::string& path) {
  std::ifstream in(path);
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

// Bit for bit, component by component.
void expect_same(const Eigen::Vector3d& a, const Eigen::Vector3d& b) {
  for (int i = 0; i < 3; ++i) EXPECT_EQ(a[i], b[i]) << "component " << i;
}

TEST(PackFacts, TheCgAndTheEyePointAreTheFlightModels) {
  for (const char* name : {"c172.yaml", "b737.yaml", "nasa_sphere.yaml", "nasa_brick.yaml"}) {
    SCOPED_TRACE(name);
    const aircraft_pack::PackFacts facts = aircraft_pack::load_pack_facts(data_pack(name));
    AircraftPack pack = load_aircraft_pack(data_pack(name));
    const Eigen::Vector3d eye = pack.geometry.pilot_eye_point_m;
    const AircraftModel model(std::move(pack), {});
    expect_same(aircraft_pack::loaded_cg_m(facts.mass), model.outputs().cg_m);
    expect_same(aircraft_pack::eye_from_cg_m(facts), eye - model.outputs().cg_m);
  }
}

TEST(PackFacts, AnotherLoadingMovesBothAlike) {
  std::string text = text_of(data_pack("c172.yaml"));
  const std::string fuel = "initial_kg: ";
  const std::size_t at = text.find(fuel);
  ASSERT_NE(at, std::string::npos);
  text.replace(at + fuel.size(), text.find('\n', at) - at - fuel.size(), "5.0");
  const aircraft_pack::PackFacts full = aircraft_pack::load_pack_facts(data_pack("c172.yaml"));
  const aircraft_pack::PackFacts light = aircraft_pack::parse_pack_facts(text, "c172 with 5 kg in a tank");
  const AircraftModel model(parse_aircraft_pack(text, "c172 with 5 kg in a tank"), {});
  expect_same(aircraft_pack::loaded_cg_m(light.mass), model.outputs().cg_m);
  EXPECT_NE(aircraft_pack::loaded_cg_m(light.mass).x(), aircraft_pack::loaded_cg_m(full.mass).x());
}

TEST(PackFacts, TheStatedStallWarningIsThePacksLift) {
  for (const char* name : {"c172.yaml", "b737.yaml"}) {
    SCOPED_TRACE(name);
    const aircraft_pack::PackFacts facts = aircraft_pack::load_pack_facts(data_pack(name));
    const aircraft_pack::StallWarningSpec& stated = aircraft_pack::stall_warning_of(facts);
    const AircraftPack pack = load_aircraft_pack(data_pack(name));
    ASSERT_EQ(stated.flap_norm.size(), 5u);
    for (std::size_t i = 0; i < stated.flap_norm.size(); ++i) {
      const double computed = stall_angles(pack, stated.flap_norm[i]).alpha_warning_rad;
      std::printf("%s flaps %.2f: stated %.17g, lift %.17g rad\n", name, stated.flap_norm[i], stated.alpha_rad[i],
                  computed);
      EXPECT_EQ(stated.alpha_rad[i], computed) << "flaps " << stated.flap_norm[i];
    }
  }
}

TEST(PackFacts, AStatedScheduleTheLiftDoesNotGiveIsRefused) {
  std::string text = text_of(data_pack("c172.yaml"));
  const std::size_t at = text.find("alpha_rad: [");
  ASSERT_NE(at, std::string::npos);
  text.replace(at, text.find(']', at) - at + 1, "alpha_rad: [0.2, 0.2, 0.2, 0.2, 0.2]");
  EXPECT_NO_THROW(aircraft_pack::parse_pack_facts(text, "wrong.yaml"));  // the facts cannot tell
  try {
    parse_aircraft_pack(text, "wrong.yaml");
    FAIL() << "a schedule the lift does not give was accepted";
  } catch (const util::ConfigError& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find("wrong.yaml"), std::string::npos) << what;
    EXPECT_NE(what.find("alpha_rad[0] is 0.20000000000000001 rad, but this pack's lift gives"), std::string::npos)
        << what;
  }
}

TEST(PackFacts, APackWithoutAScheduleSaysSo) {
  const aircraft_pack::PackFacts sphere = aircraft_pack::load_pack_facts(data_pack("nasa_sphere.yaml"));
  EXPECT_FALSE(sphere.stall_warning);
  EXPECT_THROW(aircraft_pack::stall_warning_of(sphere), std::invalid_argument);
}

}  // namespace
}  // namespace fedsim::flight
