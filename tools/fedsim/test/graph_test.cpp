// fedsim graph: the shipped deployments have a complete, matching data flow; a reader without a
// writer and a QoS mismatch are reported by name (the checks can fail).
#include "fedsim/graph.hpp"
#include "common/util/build_paths.hpp"
#include "fedsim/launcher.hpp"
#include "common/runtime/topic_catalogue.hpp"

#include <gtest/gtest.h>

#include <algorithm>

#include <filesystem>
#include <fstream>
#include <iterator>

namespace fedsim::launcher {
namespace {

namespace fs = std::filesystem;

DataFlowGraph graph_of_text(const std::string& yaml) {
  const Deployment d = parse_deployment(yaml, "test.yaml");
  return build_graph(d, deployment_vars(fedsim::util::source_dir() + "/deploy/test.yaml",
                                        testing::TempDir() + "graph_out"));
}

bool mentions(const std::vector<std::string>& lines, const std::string& text) {
  for (const auto& l : lines) {
    if (l.find(text) != std::string::npos) return true;
  }
  return false;
}

TEST(Graph, ShippedDeploymentsHaveNoProblems) {
  int checked = 0;
  for (const auto& entry : fs::directory_iterator(fedsim::util::source_dir() + "/deploy")) {
    if (entry.path().extension() != ".yaml") continue;
    SCOPED_TRACE(entry.path().string());
    const Deployment d = load_deployment(entry.path().string());
    const DataFlowGraph graph = build_graph(d, deployment_vars(entry.path().string(),
                                                               testing::TempDir() + "graph_out"));
    EXPECT_TRUE(graph.problems.empty()) << graph_text(graph);
    EXPECT_FALSE(graph.nodes.empty());
    ++checked;
  }
  EXPECT_GE(checked, 2);
}

TEST(Graph, DefaultScenarioWiresIoToFlightToNavMotionLoaderStationAndRecorder) {
  const std::string path = fedsim::util::source_dir() + "/deploy/default.yaml";
  const DataFlowGraph graph =
      build_graph(load_deployment(path), deployment_vars(path, testing::TempDir() + "graph_out"));
  const std::string dot = graph_dot(graph);
  EXPECT_NE(dot.find("\"io\" -> \"flight\" [label=\"fedsim/pilot_controls\\npilot_controls\"]"),
            std::string::npos)
      << dot;
  EXPECT_NE(dot.find("\"flight\" -> \"recorder\""), std::string::npos) << dot;
  EXPECT_NE(graph_text(graph).find("flight -> fedsim/aircraft_state -> nav, motion, control_loading, visual, displays, ios, recorder"),
            std::string::npos)
      << graph_text(graph);
  EXPECT_NE(graph_text(graph).find("nav -> fedsim/navigation_state -> displays, ios, recorder"), std::string::npos);
  // The frame clock and the station are drawn from the ports they declare; the backbone's other
  // side is the runtime in every federate.
  EXPECT_NE(dot.find("\"timing\" -> \"(every federate)\" [label=\"fedsim/frame_tick\\ntick\", style=dashed]"),
            std::string::npos) << dot;
  EXPECT_NE(dot.find("\"(every federate)\" -> \"timing\" [label=\"fedsim/frame_done\\nframe_done\", style=dashed]"),
            std::string::npos) << dot;
  EXPECT_NE(dot.find("\"ios\" -> \"timing\" [label=\"fedsim/sim_command\\ncommand\"]"), std::string::npos) << dot;
  EXPECT_EQ(dot.find("\"timing\" -> \"timing\""), std::string::npos) << "no loop: the clock reads its own status";
  EXPECT_NE(graph_text(graph).find("  timing (fedsim-timing)\n    writes fedsim/frame_tick [tick]\n"), std::string::npos)
      << graph_text(graph);
  // The loader's autopilot input is a monitor: without an autopilot it is a note, not a problem.
  EXPECT_TRUE(graph.problems.empty());
  EXPECT_NE(std::find(graph.notes.begin(), graph.notes.end(),
                      "control_loading monitors fedsim/autopilot_state: no federate writes it here"),
            graph.notes.end());
  // docs/architecture.md shows this graph: its DOT is the code's (redraw: target docs_images).
  std::ifstream committed(fedsim::util::source_dir() + "/docs/images/federation_default.dot");
  const std::string committed_dot((std::istreambuf_iterator<char>(committed)),
                                  std::istreambuf_iterator<char>());
  EXPECT_EQ(committed_dot, dot) << "docs/images/federation_default.dot is out of date";
}

TEST(Graph, TheSyncQosOfTheDeploymentIsTheClocksAndEveryFederates) {
  const DataFlowGraph graph = graph_of_text(R"(name: reliable
sync_qos: reliable
federates:
  - {name: io, binary: fedsim-io, args: [--profile, "${DATA_DIR}/profiles/elevator_doublets.csv"]}
)");
  EXPECT_TRUE(graph.problems.empty()) << graph_text(graph);
  EXPECT_NE(graph_text(graph).find("writes fedsim/frame_tick [tick_reliable]"), std::string::npos) << graph_text(graph);
  EXPECT_NE(graph_dot(graph).find("[label=\"fedsim/frame_done\\nframe_done_reliable\"]"), std::string::npos)
      << graph_dot(graph);
}

TEST(Graph, AReaderWithoutAWriterIsAProblem) {
  const DataFlowGraph graph = graph_of_text(R"(name: orphan
federates:
  - name: flight
    binary: fedsim-flight
    args: [--aircraft, c172, --trim, level, --ktas, "100"]
)");
  ASSERT_EQ(graph.problems.size(), 1u) << graph_text(graph);
  EXPECT_EQ(graph.problems[0], "flight reads fedsim/pilot_controls and no federate writes it");
  EXPECT_NE(graph_dot(graph).find("color=red"), std::string::npos);
}

TEST(Graph, AReliableReaderOfABestEffortWriterIsAQosMismatch) {
  const DataFlowGraph graph = graph_of_text(R"(name: mismatch
federates:
  - name: io
    binary: fedsim-io
    args: [--profile, "${DATA_DIR}/profiles/elevator_doublets.csv", --controls-qos, state]
  - name: flight
    binary: fedsim-flight
    args: [--aircraft, c172, --trim, level, --ktas, "100"]
)");
  EXPECT_TRUE(mentions(graph.problems, "QoS mismatch on fedsim/pilot_controls: flight reads "
                                       "reliable ('pilot_controls'), io writes best effort ('state')"))
      << graph_text(graph);
}

TEST(Graph, TwoWritersOfATopicAndAnUnknownProfileAreProblems) {
  const DataFlowGraph graph = graph_of_text(R"(name: two
federates:
  - {name: a, binary: fedsim-io, args: [--profile, "${DATA_DIR}/profiles/elevator_doublets.csv"]}
  - {name: b, binary: fedsim-io, args: [--profile, "${DATA_DIR}/profiles/elevator_doublets.csv",
                                       --controls-qos, no_such_profile]}
)");
  EXPECT_TRUE(mentions(graph.problems, "fedsim/pilot_controls has 2 writers (a, b)")) << graph_text(graph);
  EXPECT_TRUE(mentions(graph.problems, "'no_such_profile', which the QoS file does not define"))
      << graph_text(graph);
}

TEST(Graph, ThreeVisualChannelsEachOwnTheirInstancesOfTheChannelTopics) {
  const DataFlowGraph graph = graph_of_text(R"(name: three
federates:
  - {name: flight, binary: fedsim-flight, args: [--aircraft, c172, --trim, level, --ktas, "100"]}
  - {name: left, binary: fedsim-visual, args: [--channels, "${DATA_DIR}/visual/three_channels.yaml", --channel, left]}
  - {name: centre, binary: fedsim-visual, args: [--channels, "${DATA_DIR}/visual/three_channels.yaml", --channel, centre]}
  - {name: right, binary: fedsim-visual, args: [--channels, "${DATA_DIR}/visual/three_channels.yaml", --channel, right]}
)");
  // Keyed by channel: three writers of the status and picture topics are the design, while two
  // writers of a topic that is not (the test above) remain a problem.
  EXPECT_FALSE(mentions(graph.problems, "fedsim/visual_status has 3 writers")) << graph_text(graph);
  EXPECT_FALSE(mentions(graph.problems, "fedsim/visual_picture has 3 writers")) << graph_text(graph);
  ASSERT_TRUE(runtime::topics::find("fedsim/visual_status")->instance_per_writer);
  EXPECT_FALSE(runtime::topics::find("fedsim/aircraft_state")->instance_per_writer);
}

}  // namespace
}  // namespace fedsim::launcher
