// `fedsim graph <deployment>`: the data-flow graph of a deployment, from the ports the
// federates declare (the same programs `fedsim run` starts, the frame clock and the instructor
// station included, built in this process by fedsim/members.hpp without joining DDS): who
// writes and who reads each topic, with the QoS profile of each port. The backbone ports the
// runtime gives every federate (it reads the tick and the commands, writes its acknowledgement
// and status) are one node, "(every federate)". Prints
// it as text, writes Graphviz DOT (and a PNG through `dot`), and reports what cannot work: a
// topic a federate reads and nobody writes, a topic written twice, a reliable reader of a
// best-effort writer (they never match), a lockstep input whose writer is not reliable.
#pragma once

#include "common/runtime/component.hpp"
#include "fedsim/deployment.hpp"

#include <CLI/CLI.hpp>

#include <string>
#include <vector>

namespace fedsim::launcher {

struct GraphNode {
  std::string name;    // federate name
  std::string binary;  // e.g. fedsim-flight
  struct Port {
    std::string topic;
    runtime::PortDirection direction;
    std::string qos;    // profile; "(writer's)" for a recorder that matches its writer
    bool lockstep_input = false;
    bool best_effort = false;  // writes: the profile's reliability is best effort
    bool monitor = false;      // reads: a frame topic read without holding the frame (optional)
  };
  std::vector<Port> ports;
  bool ports_known = true;  // false for a binary whose ports fedsim cannot know
  bool host = false;        // not a member: the backbone ports of every federate's runtime
};

struct DataFlowGraph {
  std::string deployment;
  std::vector<GraphNode> nodes;
  std::vector<std::string> problems;  // each a sentence naming the federate and topic
  std::vector<std::string> notes;     // written and read by nobody, unknown ports...
};

/// Builds the graph of a loaded deployment (arguments substituted with `vars`). Throws
/// util::ConfigError if a federate's arguments are bad (as `fedsim run` would).
DataFlowGraph build_graph(const Deployment& deployment,
                          const std::map<std::string, std::string>& vars);
/// Text for a terminal.
std::string graph_text(const DataFlowGraph& graph);
/// Graphviz DOT: federates as boxes, one edge per writer -> reader of a topic, labelled with
/// the topic and QoS (dashed: best effort); problems in red.
std::string graph_dot(const DataFlowGraph& graph);

/// Adds `fedsim graph` to the CLI.
void add_graph_command(CLI::App& app, int& exit_code);

}  // namespace fedsim::launcher
