// The `fedsim` CLI's live-topic subcommands (the lead's tools/fedsim/main.cpp calls this):
//   fedsim topic list [-v] [--wait S]
//   fedsim topic echo <topic> [--count N] [--field a.b] [--json] [--wait S] [--timeout S]
//   fedsim topic hz <topic> [--window N] [--wait S] [--duration S]
//   fedsim record --topics t1,t2 --out DIR [--duration S] [--lockstep-member] [--name recorder]
// plus the DDS options on each (--domain, --qos-file, --participant-profile). Each subcommand runs
// from its CLI11 callback during parse; a failure throws CLI::RuntimeError(exit code), which
// CLI11_PARSE / app.exit() turn into the process exit code without printing anything more.
#pragma once

#include <CLI/CLI.hpp>

namespace fedsim::tools {

void add_topic_commands(CLI::App& app);

}  // namespace fedsim::tools
