// Federate options come from the command line, a TOML/INI file (--config) and the environment.
#include "common/runtime/federate_options.hpp"

#include <gtest/gtest.h>

#include <unistd.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>

namespace fedsim::runtime {
namespace {

int parse(CLI::App& app, std::vector<std::string> args) {
  args.insert(args.begin(), "prog");
  std::vector<char*> argv;
  for (auto& a : args) argv.push_back(a.data());
  try {
    app.parse(static_cast<int>(argv.size()), argv.data());
    return 0;
  } catch (const CLI::ParseError& e) {
    return e.get_exit_code() == 0 ? 0 : 1;
  }
}

TEST(FederateOptions, CommandLineSetsNameDomainAndProfile) {
  FederateOptions o;
  CLI::App app;
  add_federate_options(app, o, "io");
  ASSERT_EQ(parse(app, {"--domain", "12", "--participant-profile", "fedsim_shm", "--frames", "5"}), 0);
  EXPECT_EQ(o.name, "io");
  EXPECT_EQ(o.dds.domain_id, 12);
  EXPECT_EQ(o.dds.participant_profile, "fedsim_shm");
  EXPECT_EQ(o.max_frames, 5u);
  EXPECT_EQ(o.dds.qos_file, default_qos_file());
}

TEST(FederateOptions, ConfigFileProvidesOptionsAndTheCommandLineWins) {
  const auto path = std::filesystem::temp_directory_path() /
                    ("fedsim_options_test_" + std::to_string(::getpid()) + ".toml");  // runs at once apart
  std::ofstream(path) << "name = \"flight2\"\ndomain = 33\nlog-level = \"warn\"\n";
  FederateOptions o;
  CLI::App app;
  add_federate_options(app, o, "flight");
  ASSERT_EQ(parse(app, {"--config", path.string(), "--domain", "34"}), 0);
  EXPECT_EQ(o.name, "flight2");
  EXPECT_EQ(o.log_level, "warn");
  EXPECT_EQ(o.dds.domain_id, 34);
  std::filesystem::remove(path);
}

TEST(FederateOptions, DomainFromTheEnvironmentAndOutOfRangeRejected) {
  setenv("FEDSIM_DOMAIN", "21", 1);
  FederateOptions o;
  CLI::App app;
  add_federate_options(app, o, "x");
  unsetenv("FEDSIM_DOMAIN");
  ASSERT_EQ(parse(app, {}), 0);
  EXPECT_EQ(o.dds.domain_id, 21);
  FederateOptions bad;
  CLI::App app2;
  add_federate_options(app2, bad, "x");
  EXPECT_NE(parse(app2, {"--domain", "400"}), 0);
}

}  // namespace
}  // namespace fedsim::runtime
