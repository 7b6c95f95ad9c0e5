// The IDL is the contract: every floating-point field of every message names its unit with the
// one suffix docs/frames.md gives it, or says [-] (dimensionless) in its comment; a unit in
// brackets in the comment agrees with the suffix; no field uses the retired _rps (rad/s) or a
// _b frame token. Parses idl/*.idl as the repository has them.
#include <gtest/gtest.h>
#include "common/util/build_paths.hpp"

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <map>
#include <regex>
#include <string>
#include <vector>

namespace fs = std::filesystem;

namespace {

/// docs/frames.md's suffixes and the unit text a comment may give for each.
const std::map<std::string, std::vector<std::string>>& suffixes() {
  static const std::map<std::string, std::vector<std::string>> table = {
      {"m", {"m"}},        {"s", {"s"}},         {"ms", {"ms"}},       {"us", {"us"}},
      {"ns", {"ns"}},      {"mps", {"m/s"}},     {"mps2", {"m/s^2"}},  {"rad", {"rad"}},
      {"radps", {"rad/s"}}, {"radps2", {"rad/s^2"}}, {"n", {"N"}},     {"nm", {"N m"}},
      {"pa", {"Pa"}},      {"k", {"K"}},         {"kg", {"kg"}},       {"kgps", {"kg/s"}},
      {"kgpm3", {"kg/m^3"}}, {"kgm2", {"kg m^2"}}, {"w", {"W"}},      {"rpm", {"rev/min"}},
      {"pct", {"%", "% of rated"}}, {"hz", {"Hz"}}, {"norm", {"-"}}, {"ps", {"1/s"}},
      {"mps_per_m", {"1/s", "m/s per m"}}};
  return table;
}

struct Field {
  std::string file;
  int line = 0;
  std::string name;
  std::string comment;
};

std::vector<Field> floating_fields() {
  const std::regex field(R"(^\s*(double|float)\s+(\w+)(\[\d+\])?;\s*//(.*)$)");
  const std::regex uncommented(R"(^\s*(double|float)\s+(\w+)(\[\d+\])?;\s*$)");
  std::vector<Field> out;
  for (const auto& entry : fs::directory_iterator(fedsim::util::source_dir() + "/idl")) {
    if (entry.path().extension() != ".idl") continue;
    std::ifstream in(entry.path());
    int n = 0;
    for (std::string line; std::getline(in, line);) {
      ++n;
      std::smatch m;
      if (std::regex_match(line, m, field)) {
        out.push_back({entry.path().filename().string(), n, m[2], m[4]});
      } else if (std::regex_match(line, m, uncommented)) {
        out.push_back({entry.path().filename().string(), n, m[2], ""});
      }
    }
  }
  return out;
}

std::string suffix_of(const std::string& name) {
  if (suffixes().count(name)) return name;  // a field named after its unit ("rpm")
  std::smatch compound;  // a ratio of two units: "wind_gradient_mps_per_m"
  if (std::regex_search(name, compound, std::regex("_([a-z0-9]+_per_[a-z0-9]+)$")) &&
      suffixes().count(compound[1])) {
    return compound[1];
  }
  const auto underscore = name.rfind('_');
  if (underscore == std::string::npos) return "";
  const std::string s = name.substr(underscore + 1);
  return suffixes().count(s) ? s : "";
}

std::string bracket_unit(const std::string& comment) {
  const auto close = comment.rfind(']');
  const auto open = comment.rfind('[', close);
  if (close == std::string::npos || open == std::string::npos) return "";
  return comment.substr(open + 1, close - open - 1);
}

TEST(IdlConventions, EveryFloatingFieldNamesItsUnitOrSaysDimensionless) {
  const auto fields = floating_fields();
  ASSERT_GT(fields.size(), 100u);  // the parser found the messages
  for (const Field& f : fields) {
    SCOPED_TRACE(f.file + ":" + std::to_string(f.line) + ": " + f.name);
    EXPECT_EQ(f.name.find("_rps"), std::string::npos) << "rad/s is _radps";
    EXPECT_FALSE(std::regex_search(f.name, std::regex("_b(_|$)"))) << "the body frame is _body";
    const std::string suffix = suffix_of(f.name);
    const std::string unit = bracket_unit(f.comment);
    if (suffix.empty()) {
      EXPECT_EQ(unit, "-") << "no unit suffix and no [-]: say which";
      continue;
    }
    if (unit.empty() || unit == "-") continue;
    const auto& accepted = suffixes().at(suffix);
    EXPECT_NE(std::find(accepted.begin(), accepted.end(), unit), accepted.end())
        << "suffix _" << suffix << " but the comment says [" << unit << "]";
  }
}

TEST(IdlConventions, TheCheckCanFail) {
  // Negative control of the helpers above: a name without a suffix is found, a wrong bracket
  // unit is seen.
  EXPECT_EQ(suffix_of("elevator"), "");
  EXPECT_EQ(suffix_of("tas_mps"), "mps");
  EXPECT_EQ(suffix_of("rpm"), "rpm");
  EXPECT_EQ(suffix_of("wind_gradient_mps_per_m"), "mps_per_m");
  EXPECT_EQ(bracket_unit(" true airspeed [m/s]"), "m/s");
  EXPECT_EQ(bracket_unit(" no unit here"), "");
}

}  // namespace
