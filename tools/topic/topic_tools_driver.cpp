// Stand-in for the `fedsim` binary while tools/fedsim/ does not exist: only the topic commands.
// `topic_tools_driver topic list` == `fedsim topic list`.
#include "tools/topic/topic_commands.hpp"

#include "common/runtime/shutdown.hpp"

int main(int argc, char** argv) {
  fedsim::runtime::install_shutdown_handler();  // before any thread: SIGINT/SIGTERM stop cleanly
  CLI::App app{"topic_tools_driver: the `fedsim topic` and `fedsim record` commands"};
  app.require_subcommand(1);
  fedsim::tools::add_topic_commands(app);
  CLI11_PARSE(app, argc, argv);
  return 0;
}
