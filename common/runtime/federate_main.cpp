#include "common/runtime/federate_main.hpp"

#include "common/runtime/federate.hpp"
#include "common/runtime/shutdown.hpp"

#include <iostream>

namespace fedsim::runtime {

int federate_main(int argc, char** argv, const FederateProgram& program) {
  install_shutdown_handler();
  FederateOptions common;
  bool print_ports = false;
  CLI::App app{program.program + ": " + program.description};
  add_federate_options(app, common, program.default_name);
  app.add_flag("--print-ports", print_ports,
               "print the topics this federate reads and writes (JSON) and exit without joining");
  if (program.add_options) program.add_options(app);
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    return app.exit(e) == 0 ? kExitOk : kExitBadInput;  // --help is not an error
  }

  std::unique_ptr<Component> component;
  try {
    component = program.make_component(common);
  } catch (const ProgramError& e) {
    std::cerr << program.program << ": " << e.what() << "\n";
    return e.exit_code();
  } catch (const std::exception& e) {
    std::cerr << program.program << ": " << e.what() << "\n";
    return kExitBadInput;
  }
  if (print_ports) {
    std::cout << ports_json(*component) << std::endl;
    return kExitOk;
  }
  try {
    Federate federate(common);
    return federate.run(*component);
  } catch (const std::exception& e) {
    std::cerr << program.program << ": " << e.what() << "\n";
    return kExitBadInput;
  }
}

}  // namespace fedsim::runtime
