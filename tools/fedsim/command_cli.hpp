// `fedsim command ...`: sends instructor commands (fedsim/sim_command) from a terminal: run,
// freeze, reset, reposition, weather, failures, shutdown. Reliable and transient-local, so a
// federate that joins later still receives the latest command of each kind.
#pragma once

#include <CLI/CLI.hpp>

namespace fedsim::launcher {

/// Registers `fedsim command <run|freeze|reset|reposition|weather|fail|restore|shutdown>`.
void add_command_commands(CLI::App& app, int& exit_code);

}  // namespace fedsim::launcher
