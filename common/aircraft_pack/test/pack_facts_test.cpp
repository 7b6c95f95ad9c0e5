// An aircraft pack's facts without the flight model: a bare name finds the shipped pack, an
// unknown one is refused naming both places; the common sections are read and checked as the
// flight model's loader checks them (a bad stall-warning schedule, an unknown section refused by
// file and line); the eye point is the pilot's, from the loaded CG. That these numbers are the
// flight model's own, bit for bit, is federates/flight/model/aircraft/test/
// pack_facts_agreement_test.cpp (it needs the flight model).
#include "common/aircraft_pack/pack_facts.hpp"
#include "common/aircraft_pack/pack_path.hpp"
#include "common/util/build_paths.hpp"
#include "common/util/config_node.hpp"

#include <gtest/gtest.h>

#include <fstream>
#include <sstream>
#include <stdexcept>
#include <string>

namespace fedsim::aircraft_pack {
namespace {

std::string c172_text() {
  std::ifstream in(util::data_dir() + "/aircraft/c172.yaml");
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

// The c172's text with `from` (which must be there) replaced by `to`.
std::string c172_with(const std::string& from, const std::string& to) {
  std::string text = c172_text();
  const std::size_t at = text.find(from);
  EXPECT_NE(at, std::string::npos) << from;
  return text.replace(at, from.size(), to);
}

std::string error_of(const std::string& yaml) {
  try {
    parse_pack_facts(yaml, "test.yaml");
  } catch (const util::ConfigError& e) {
    return e.what();
  }
  return "";
}

TEST(PackPath, ABareNameIsTheShippedPack) {
  const std::string path = util::data_dir() + "/aircraft/c172.yaml";
  EXPECT_EQ(resolve_pack_path("c172"), path);
  EXPECT_EQ(resolve_pack_path("c172.yaml"), path);
  EXPECT_EQ(resolve_pack_path(path), path);
  try {
    resolve_pack_path("concorde");
    FAIL() << "an unknown pack was found";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("unknown aircraft pack 'concorde': no such file, and no concorde(.yaml) in"),
              std::string::npos)
        << e.what();
  }
}

TEST(PackFacts, TheC172sFacts) {
  const PackFacts facts = load_pack_facts(resolve_pack_path("c172"));
  EXPECT_EQ(facts.metadata.name.find("Cessna 172"), 0u) << facts.metadata.name;
  ASSERT_TRUE(facts.stall_warning);
  EXPECT_EQ(facts.stall_warning->flap_norm.size(), facts.stall_warning->alpha_rad.size());
  const Eigen::Vector3d eye = eye_from_cg_m(facts);
  EXPECT_GT(eye.x(), 0.0);  // ahead of the CG
  EXPECT_LT(eye.z(), 0.0);  // above it
  EXPECT_LT(eye.norm(), 3.0);
}

TEST(PackFacts, BadSchedulesAreRefusedByFileAndLine) {
  EXPECT_EQ(error_of(c172_text()), "");  // the control: the shipped text reads
  EXPECT_NE(error_of(c172_with("flap_norm: [0, 0.25, 0.5, 0.75, 1]", "flap_norm: [0, 0.25, 0.5, 0.75, 1.5]"))
                .find("flap settings lie in [0, 1]"),
            std::string::npos);
  EXPECT_NE(error_of(c172_with("flap_norm: [0, 0.25, 0.5, 0.75, 1]", "flap_norm: [0, 0.5, 0.25, 0.75, 1]"))
                .find("strictly increasing"),
            std::string::npos);
  EXPECT_NE(error_of(c172_with("alpha_rad: [0.254, 0.252,", "alpha_rad: [0.254,")).find("expected 5 numbers, got 4"),
            std::string::npos);
  EXPECT_NE(error_of(c172_with("alpha_rad: [0.254,", "alpha_rad: [.nan,")).find("test.yaml:"), std::string::npos);
  EXPECT_NE(error_of(c172_with("alpha_rad: [0.254,", "alpha_rad: [1.5,")).find("each angle of attack in [0, 1] rad"),
            std::string::npos);
  EXPECT_NE(error_of(c172_with("stall_warning:", "stall_warnings:")).find("stall_warnings"), std::string::npos);
}

}  // namespace
}  // namespace fedsim::aircraft_pack
