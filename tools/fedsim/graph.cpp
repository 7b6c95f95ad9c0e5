#include "fedsim/graph.hpp"

#include "common/runtime/federate_options.hpp"
#include "common/runtime/topic_catalogue.hpp"
#include "common/util/config_node.hpp"
#include "fedsim/launcher.hpp"
#include "fedsim/members.hpp"

#include <fastrtps/attributes/PublisherAttributes.h>
#include <fastrtps/attributes/SubscriberAttributes.h>
#include <fastrtps/xmlparser/XMLProfileManager.h>

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <map>
#include <optional>
#include <set>
#include <sstream>

namespace fs = std::filesystem;

namespace fedsim::launcher {

namespace {

constexpr const char* kWritersQos = "(writer's)";
constexpr const char* kEveryFederate = "(every federate)";

/// A `fedsim record` member reads its topics with its writers' QoS.
GraphNode recorder_node(const Member& m) {
  GraphNode node{m.spec->name, "fedsim " + (m.args.empty() ? std::string() : m.args.front()), {}, false};
  const auto recorder = recorder_of(m);
  if (!recorder) return node;
  for (const auto& t : recorder->topics) node.ports.push_back({t, runtime::PortDirection::kRead, kWritersQos, true});
  node.ports_known = true;
  return node;
}

GraphNode component_node(const Deployment& d, const Member& m) {
  const auto component = build_component(d, m);
  if (!component) return {m.spec->name, m.binary, {}, false};
  GraphNode node{m.spec->name, m.binary, {}, true};
  for (const auto& port : component->ports()) {
    const runtime::PortInfo& p = port->info();
    GraphNode::Port out{p.topic->name, p.direction, p.qos, p.lockstep_input};
    out.monitor = p.direction == runtime::PortDirection::kRead &&
                  (p.monitor || (p.topic->lockstep_input && !p.lockstep_input));
    node.ports.push_back(out);
  }
  return node;
}

/// The backbone ports the runtime gives every federate it hosts (runtime::Federate): it reads
/// the tick and the commands, and writes the acknowledgement and the status. One node stands
/// for all of them, so that the frame clock's and the station's backbone ports have their other
/// side. Its reads are monitors: with no clock in the deployment, nothing is missing for them.
GraphNode every_federate(const std::string& sync_suffix) {
  using runtime::PortDirection;
  namespace topics = runtime::topics;
  namespace qos = runtime::qos;
  GraphNode node{kEveryFederate, "the runtime", {}, true};
  node.host = true;
  node.ports.push_back({topics::frame_tick.name(), PortDirection::kRead, std::string(qos::kTick) + sync_suffix});
  node.ports.push_back({topics::sim_command.name(), PortDirection::kRead, std::string(qos::kCommand)});
  node.ports.push_back({topics::frame_done.name(), PortDirection::kWrite, std::string(qos::kFrameDone) + sync_suffix});
  node.ports.push_back({topics::federate_status.name(), PortDirection::kWrite, std::string(qos::kStatus)});
  for (auto& port : node.ports) port.monitor = port.direction == PortDirection::kRead;
  return node;
}

/// Reliability of a profile of the QoS file (true = reliable), or nullopt if unknown.
class QosProfiles {
 public:
  explicit QosProfiles(const std::string& file) {
    using eprosima::fastrtps::xmlparser::XMLProfileManager;
    loaded_ = XMLProfileManager::loadXMLFile(file) == eprosima::fastrtps::xmlparser::XMLP_ret::XML_OK;
  }
  std::optional<bool> writer_reliable(const std::string& profile) const {
    using eprosima::fastrtps::xmlparser::XMLProfileManager;
    eprosima::fastrtps::PublisherAttributes attributes;
    if (!loaded_ || XMLProfileManager::fillPublisherAttributes(profile, attributes, false) !=
                        eprosima::fastrtps::xmlparser::XMLP_ret::XML_OK) {
      return std::nullopt;
    }
    return attributes.qos.m_reliability.kind == eprosima::fastrtps::RELIABLE_RELIABILITY_QOS;
  }
  std::optional<bool> reader_reliable(const std::string& profile) const {
    using eprosima::fastrtps::xmlparser::XMLProfileManager;
    eprosima::fastrtps::SubscriberAttributes attributes;
    if (!loaded_ || XMLProfileManager::fillSubscriberAttributes(profile, attributes, false) !=
                        eprosima::fastrtps::xmlparser::XMLP_ret::XML_OK) {
      return std::nullopt;
    }
    return attributes.qos.m_reliability.kind == eprosima::fastrtps::RELIABLE_RELIABILITY_QOS;
  }

 private:
  bool loaded_ = false;
};

struct TopicUse {
  std::vector<std::pair<const GraphNode*, const GraphNode::Port*>> writers, readers;
};

std::map<std::string, TopicUse> uses_of(const DataFlowGraph& graph) {
  std::map<std::string, TopicUse> uses;
  for (const GraphNode& node : graph.nodes) {
    for (const GraphNode::Port& port : node.ports) {
      auto& use = uses[port.topic];
      (port.direction == runtime::PortDirection::kWrite ? use.writers : use.readers)
          .emplace_back(&node, &port);
    }
  }
  return uses;
}

void check(DataFlowGraph& graph, const QosProfiles& qos, bool lockstep) {
  for (const GraphNode& node : graph.nodes) {
    if (!node.ports_known) {
      graph.notes.push_back(node.name + " (" + node.binary +
                            "): ports unknown (not a fedsim component program)");
    }
  }
  for (const auto& [topic, use] : uses_of(graph)) {
    if (use.writers.empty()) {
      for (const auto& [reader, port] : use.readers) {
        if (port->monitor) {  // an optional input (the loader's autopilot back-drive)
          graph.notes.push_back(reader->name + " monitors " + topic + ": no federate writes it here");
        } else {
          graph.problems.push_back(reader->name + " reads " + topic + " and no federate writes it");
        }
      }
    }
    if (use.readers.empty()) graph.notes.push_back(topic + " is written and read by nobody here");
    const runtime::TopicInfo* info = runtime::topics::find(topic);
    // The backbone has a writer per federate (status) or per instructor tool (commands).
    const bool per_writer = info != nullptr && (info->instance_per_writer || runtime::topics::is_backbone(topic));
    if (use.writers.size() > 1 && !per_writer) {
      std::string names;
      for (const auto& [writer, port] : use.writers) names += (names.empty() ? "" : ", ") + writer->name;
      graph.problems.push_back(topic + " has " + std::to_string(use.writers.size()) +
                               " writers (" + names + "): one writer owns a topic's instances");
    }
    for (const auto& [writer, wport] : use.writers) {
      const auto writer_reliable = qos.writer_reliable(wport->qos);
      if (!writer_reliable) {
        graph.problems.push_back(writer->name + " writes " + topic + " with QoS profile '" +
                                 wport->qos + "', which the QoS file does not define");
        continue;
      }
      for (const auto& [reader, rport] : use.readers) {
        if (rport->qos == kWritersQos) {
          if (lockstep && !*writer_reliable) {
            graph.problems.push_back(reader->name + " records " + topic + " in lockstep from " +
                                     writer->name + "'s best-effort writer ('" + wport->qos +
                                     "'): a lost sample is never recorded");
          }
          continue;
        }
        const auto reader_reliable = qos.reader_reliable(rport->qos);
        if (!reader_reliable) {
          graph.problems.push_back(reader->name + " reads " + topic + " with QoS profile '" +
                                   rport->qos + "', which the QoS file does not define");
        } else if (*reader_reliable && !*writer_reliable) {
          graph.problems.push_back("QoS mismatch on " + topic + ": " + reader->name +
                                   " reads reliable ('" + rport->qos + "'), " + writer->name +
                                   " writes best effort ('" + wport->qos + "'): they never match");
        } else if (lockstep && rport->lockstep_input && !*writer_reliable) {
          graph.notes.push_back(reader->name + " waits for " + topic + " every frame, and " +
                                writer->name + " writes it best effort: a lost sample costs "
                                "the input timeout");
        }
      }
    }
  }
}

std::string dot_id(const std::string& name) { return "\"" + name + "\""; }

}  // namespace

DataFlowGraph build_graph(const Deployment& d, const std::map<std::string, std::string>& vars) {
  DataFlowGraph graph;
  graph.deployment = d.name;
  const Members members(d, vars);
  for (const Member& m : members.all()) {
    graph.nodes.push_back(m.binary == "fedsim" ? recorder_node(m) : component_node(d, m));
  }
  graph.nodes.push_back(every_federate(d.sync_qos == "reliable" ? std::string(runtime::qos::kReliableSuffix) : ""));
  const QosProfiles qos(substitute(d.qos_file, vars));
  for (GraphNode& node : graph.nodes) {
    for (GraphNode::Port& port : node.ports) {
      if (port.direction == runtime::PortDirection::kWrite) {
        port.best_effort = !qos.writer_reliable(port.qos).value_or(true);
      }
    }
  }
  check(graph, qos, d.mode == "lockstep");
  return graph;
}

std::string graph_text(const DataFlowGraph& graph) {
  std::ostringstream out;
  const auto members = std::count_if(graph.nodes.begin(), graph.nodes.end(), [](const GraphNode& n) { return !n.host; });
  out << "deployment " << graph.deployment << ": " << members << " federates, the frame clock included; "
      << kEveryFederate << " stands for the backbone ports the runtime gives each one\n";
  for (const GraphNode& node : graph.nodes) {
    if (node.host) continue;
    out << "  " << node.name << " (" << node.binary << ")\n";
    for (const auto& p : node.ports) {
      out << "    " << (p.direction == runtime::PortDirection::kRead ? "reads  " : "writes ")
          << p.topic << " [" << p.qos << "]" << (p.lockstep_input && p.direction == runtime::PortDirection::kRead ? " lockstep input" : "")
          << "\n";
    }
  }
  out << "data flow:\n";
  for (const auto& [topic, use] : uses_of(graph)) {
    std::string writers, readers;
    for (const auto& [n, p] : use.writers) writers += (writers.empty() ? "" : ", ") + n->name;
    for (const auto& [n, p] : use.readers) readers += (readers.empty() ? "" : ", ") + n->name;
    out << "  " << (writers.empty() ? "(nobody)" : writers) << " -> " << topic << " -> "
        << (readers.empty() ? "(nobody)" : readers) << "\n";
  }
  for (const auto& n : graph.notes) out << "note: " << n << "\n";
  for (const auto& p : graph.problems) out << "PROBLEM: " << p << "\n";
  if (graph.problems.empty()) out << "no problems found\n";
  return out.str();
}

std::string graph_dot(const DataFlowGraph& graph) {
  std::ostringstream out;
  out << "digraph " << dot_id(graph.deployment) << " {\n"
      << "  rankdir=LR;\n  node [shape=box, style=rounded, fontname=\"Helvetica\"];\n"
      << "  edge [fontname=\"Helvetica\", fontsize=10];\n"
      << "  labelloc=t; label=" << dot_id("fedsim deployment " + graph.deployment) << ";\n";
  for (const GraphNode& node : graph.nodes) {
    out << "  " << dot_id(node.name) << " [label=" << dot_id(node.name + "\\n" + node.binary)
        << (node.host ? ", style=\"rounded,dotted\"" : node.ports_known ? "" : ", style=dashed") << "];\n";
  }
  for (const auto& [topic, use] : uses_of(graph)) {
    if (use.writers.empty()) {
      out << "  " << dot_id("? " + topic) << " [shape=plaintext, fontcolor=red];\n";
      for (const auto& [reader, port] : use.readers) {
        out << "  " << dot_id("? " + topic) << " -> " << dot_id(reader->name)
            << " [color=red, label=" << dot_id(topic + "\\nno writer") << "];\n";
      }
    }
    for (const auto& [writer, wport] : use.writers) {
      const bool best_effort = wport->best_effort;
      if (use.readers.empty()) {
        out << "  " << dot_id(topic + " ") << " [shape=plaintext, fontcolor=gray40];\n"
            << "  " << dot_id(writer->name) << " -> " << dot_id(topic + " ")
            << " [color=gray40" << (best_effort ? ", style=dashed" : "") << "];\n";
      }
      for (const auto& [reader, rport] : use.readers) {
        if (reader == writer) continue;  // the clock reads the status and commands it writes
        out << "  " << dot_id(writer->name) << " -> " << dot_id(reader->name) << " [label="
            << dot_id(topic + "\\n" + wport->qos) << (best_effort ? ", style=dashed" : "")
            << "];\n";
      }
    }
  }
  out << "}\n";
  return out.str();
}

void add_graph_command(CLI::App& app, int& exit_code) {
  struct Options {
    std::string deployment, dot, png;
  };
  auto o = std::make_shared<Options>();
  auto* cmd = app.add_subcommand("graph", "print the data-flow graph of a deployment (from the "
                                          "federates' declared ports) and report what cannot work");
  cmd->add_option("deployment", o->deployment, "deployment file (YAML)")->required();
  cmd->add_option("--dot", o->dot, "also write the graph as Graphviz DOT to this file");
  cmd->add_option("--png", o->png, "also draw it to this PNG (needs Graphviz's dot)");
  cmd->callback([o, &exit_code] {
    try {
      const Deployment d = load_deployment(o->deployment);
      const DataFlowGraph graph = build_graph(d, deployment_vars(o->deployment, "out/" + d.name));
      std::cout << graph_text(graph);
      const std::string dot = graph_dot(graph);
      if (!o->dot.empty()) {
        std::ofstream(o->dot) << dot;
      }
      if (!o->png.empty()) {
        if (o->png.find('\'') != std::string::npos) throw std::invalid_argument("--png: no quotes, please");
        const std::string tmp = o->png + ".dot";
        std::ofstream(tmp) << dot;
        const std::string command = "dot -Tpng -o '" + o->png + "' '" + tmp + "'";
        const int rc = std::system(command.c_str());
        fs::remove(tmp);
        if (rc != 0) throw std::runtime_error("could not draw " + o->png + " (is Graphviz installed?)");
        std::cout << "drawn: " << o->png << "\n";
      }
      exit_code = graph.problems.empty() ? 0 : 1;
    } catch (const runtime::ProgramError& e) {
      std::cerr << "fedsim graph: " << e.what() << "\n";
      exit_code = 2;
    } catch (const std::exception& e) {
      std::cerr << "fedsim graph: " << e.what() << "\n";
      exit_code = 2;
    }
  });
}

}  // namespace fedsim::launcher
