#include "common/runtime/federate_options.hpp"
#include "common/util/build_paths.hpp"

#include <cstdlib>
#include <iostream>
#include "common/util/cli_checks.hpp"

#include "common/runtime/topic_catalogue.hpp"

#include <cstdlib>
#include <map>

namespace fedsim::runtime {

std::string default_qos_file() {
  if (const char* env = std::getenv("FEDSIM_QOS_FILE"); env && *env) return env;
  return util::qos_file();
}

void add_dds_options(CLI::App& app, ParticipantOptions& options) {
  options.qos_file = default_qos_file();
  if (const char* env = std::getenv("FEDSIM_DOMAIN"); env && *env) {
    // Checked here, before anything joins: "abc" once meant domain 0, silently.
    char* end = nullptr;
    const long domain = std::strtol(env, &end, 10);
    if (end == env || *end != '\0' || domain < 0 || domain > 232) {
      std::cerr << "FEDSIM_DOMAIN: '" << env << "' is not a DDS domain id (0..232)\n";
      std::exit(2);
    }
    options.domain_id = static_cast<int>(domain);
  }
  if (const char* env = std::getenv("FEDSIM_PARTICIPANT_PROFILE"); env && *env) {
    options.participant_profile = env;
  }
  app.add_option("--domain", options.domain_id, "DDS domain id (env FEDSIM_DOMAIN)")
      ->check(fedsim::util::FiniteRange(0, 232))
      ->capture_default_str();
  app.add_option("--qos-file", options.qos_file, "Fast DDS XML QoS profiles (env FEDSIM_QOS_FILE)")
      ->capture_default_str();
  app.add_option("--participant-profile", options.participant_profile,
                 "participant profile in the QoS file; fedsim_loopback keeps traffic on "
                 "127.0.0.1, fedsim_lan leaves the host (env FEDSIM_PARTICIPANT_PROFILE)")
      ->capture_default_str();
}

void add_sync_qos_option(CLI::App& app, std::string& suffix, const std::string& description) {
  // A value outside the two is an error (CheckedTransformer), never silently the default.
  const std::map<std::string, std::string> suffixes{
      {"best_effort", ""}, {"reliable", std::string(qos::kReliableSuffix)}};
  app.add_option("--sync-qos", suffix, description)
      ->transform(CLI::CheckedTransformer(suffixes))
      ->default_str("best_effort");
}

void add_federate_options(CLI::App& app, FederateOptions& options,
                          const std::string& default_name) {
  options.name = default_name;
  app.set_config("--config", "", "read options from a TOML/INI file");
  app.add_option("--name", options.name, "federate name, unique in the federation")
      ->capture_default_str();
  add_dds_options(app, options.dds);
  app.add_option("--log-level", options.log_level, "trace|debug|info|warn|error")
      ->check(CLI::IsMember({"trace", "debug", "info", "warn", "error", "critical", "off"}))
      ->capture_default_str();
  app.add_option("--duration", options.duration_s, "stop after this many seconds (0 = no limit)")
      ->check(fedsim::util::kFiniteNonNegative);
  app.add_option("--frames", options.max_frames, "stop after stepping this many frames (0 = no limit)");
  add_sync_qos_option(app, options.sync_qos_suffix,
                      "QoS of the frame tick and acknowledgement: best_effort (the timing federate "
                      "repeats a tick whose acknowledgements are overdue) or reliable (the "
                      "middleware repairs losses; slower)");
  app.add_option("--input-timeout", options.input_timeout_s,
                 "lockstep: seconds to wait for a missing input before stepping without it")
      ->check(fedsim::util::kFinitePositive)
      ->capture_default_str();
  app.add_option("--silent-frames", options.silent_frames,
                 "report a matched writer of a per-frame topic (state, controls) that wrote "
                 "nothing for this many frames, as fault silent_writer (0 = never)")
      ->check(fedsim::util::FiniteRange(std::uint64_t{0}, std::uint64_t{1000000}))
      ->capture_default_str();
}

}  // namespace fedsim::runtime
