// The main() of every component federate: parse the common options and the federate's own,
// build the component (all input checked before anything is sent), then either print its ports
// (--print-ports, for `fedsim graph`) or join the federation and run it.
//
// Exit codes: 0 clean stop; 1 failed while running (step failed, faults counted); 2 bad input
// (options, files: the message names what and where; nothing was sent); other codes a program
// chooses through ProgramError (fedsim-flight: 3, the trim did not converge).
#pragma once

#include "common/runtime/component.hpp"
#include "common/runtime/federate_options.hpp"

#include <CLI/CLI.hpp>

#include <functional>
#include <memory>
#include <stdexcept>
#include <string>

namespace fedsim::runtime {

inline constexpr int kExitOk = 0;
inline constexpr int kExitFailed = 1;
inline constexpr int kExitBadInput = 2;

/// A start-up failure with its own exit code.
class ProgramError : public std::runtime_error {
 public:
  ProgramError(int exit_code, const std::string& message)
      : std::runtime_error(message), exit_code_(exit_code) {}
  int exit_code() const { return exit_code_; }

 private:
  int exit_code_;
};

struct FederateProgram {
  std::string program;       // executable name for messages, e.g. "fedsim-flight"
  std::string default_name;  // default federate name, e.g. "flight"
  std::string description;   // one line for --help
  /// Adds the federate's own options (the common ones are added for it).
  std::function<void(CLI::App&)> add_options;
  /// Builds the component from the parsed options. Throws for bad input (exit 2, or the
  /// ProgramError's code).
  std::function<std::unique_ptr<Component>(const FederateOptions&)> make_component;
};

int federate_main(int argc, char** argv, const FederateProgram& program);

}  // namespace fedsim::runtime
