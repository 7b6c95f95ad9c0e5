// The instructor station as a component, without DDS: the ports it declares (what --print-ports
// and fedsim graph show: monitors, never holding a frame), and the station composed in-process
// as `fedsim run --in-process` runs it: its page served, the live fields from the composition's
// topics, a command from the page into the composition (the next frame frozen). A public address
// without a token is refused before anything runs.
#include "ios/ios_station.hpp"

#include "common/runtime/composition.hpp"
#include "ios/server/web_server.hpp"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <arpa/inet.h>
#include <netinet/in.h>
#include <sys/socket.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>

namespace fedsim::ios {
namespace {

namespace fs = std::filesystem;

std::unique_ptr<runtime::Component> station(std::vector<std::string> args) {
  runtime::FederateProgram program = ios::program();
  runtime::FederateOptions common;
  CLI::App app{program.program};
  runtime::add_federate_options(app, common, program.default_name);
  program.add_options(app);
  std::reverse(args.begin(), args.end());
  app.parse(args);
  return program.make_component(common);
}

/// One HTTP/1.0 exchange on the loopback: the status code and the body.
std::pair<int, std::string> http(int port, const std::string& method, const std::string& path,
                                 const std::string& body = "") {
  const int fd = ::socket(AF_INET, SOCK_STREAM, 0);
  sockaddr_in address{};
  address.sin_family = AF_INET;
  address.sin_port = htons(static_cast<std::uint16_t>(port));
  address.sin_addr.s_addr = htonl(INADDR_LOOPBACK);
  if (::connect(fd, reinterpret_cast<sockaddr*>(&address), sizeof(address)) != 0) {
    ::close(fd);
    return {0, ""};
  }
  const std::string request = method + " " + path + " HTTP/1.0\r\nHost: 127.0.0.1\r\nContent-Type: application/json\r\n" +
                              "Content-Length: " + std::to_string(body.size()) + "\r\n\r\n" + body;
  ::send(fd, request.data(), request.size(), 0);
  std::string reply;
  char buffer[4096];
  for (ssize_t n; (n = ::recv(fd, buffer, sizeof(buffer), 0)) > 0;) reply.append(buffer, static_cast<std::size_t>(n));
  ::close(fd);
  const auto space = reply.find(' ');
  const auto blank = reply.find("\r\n\r\n");
  if (space == std::string::npos || blank == std::string::npos) return {0, reply};
  return {std::stoi(reply.substr(space + 1, 3)), reply.substr(blank + 4)};
}

/// An aircraft that climbs a metre a frame.
class Climbing final : public runtime::Component {
 public:
  Climbing() : Component("flight"), out_(writes(runtime::topics::aircraft_state)) {}
  void step(const runtime::FrameContext& frame) override {
    msg::AircraftState s;
    s.altitude_msl_m(1000.0 + static_cast<double>(frame.frame));
    s.stamp(frame.end_stamp());
    out_.write(s);
  }

 private:
  runtime::Output<msg::AircraftState>& out_;
};

TEST(StationComponent, DeclaresItsMonitorsAndWhatItWrites) {
  const auto ios = station({});
  std::vector<std::string> reads, writes;
  for (const auto& port : ios->ports()) {
    const runtime::PortInfo& p = port->info();
    if (p.direction == runtime::PortDirection::kWrite) {
      writes.push_back(p.topic->name);
    } else {
      reads.push_back(p.topic->name + " " + p.qos);
      EXPECT_TRUE(p.monitor) << p.topic->name << ": a monitor never holds a frame";
      EXPECT_FALSE(p.lockstep_input) << p.topic->name;
    }
  }
  EXPECT_EQ(writes, (std::vector<std::string>{"fedsim/sim_command", "fedsim/replay_state"}));
  EXPECT_NE(std::find(reads.begin(), reads.end(), "fedsim/aircraft_state state"), reads.end());
  EXPECT_NE(std::find(reads.begin(), reads.end(), "fedsim/pilot_controls pilot_controls"), reads.end())
      << "its writer's exclusive ownership: a shared-ownership reader would never match";
  EXPECT_NE(std::find(reads.begin(), reads.end(), "fedsim/federate_status status"), reads.end());
  EXPECT_NE(std::find(reads.begin(), reads.end(), "fedsim/visual_picture picture"), reads.end());
}

TEST(StationComponent, RefusesAPublicAddressWithoutATokenBeforeRunning) {
  try {
    station({"--bind", "0.0.0.0", "--http-port", "0"});
    FAIL() << "accepted";
  } catch (const ServerError& e) {
    EXPECT_NE(std::string(e.what()).find("give an access token"), std::string::npos) << e.what();
  }
}

TEST(StationComponent, InProcessServesTheCompositionAndSendsCommandsIntoIt) {
  const fs::path dir = fs::path(testing::TempDir()) / "station_in_process";
  fs::create_directories(dir);
  const auto ios = station({"--http-port", "0", "--port-file", (dir / "ios.port").string(), "--push-hz", "20"});
  Climbing flight;
  runtime::Composition composition({50.0, false});
  std::vector<msg::SimCommand> sent;
  composition.on_written(runtime::topics::sim_command, std::function<void(const msg::SimCommand&)>(
                                                           [&](const msg::SimCommand& c) {
                                                             sent.push_back(c);
                                                             composition.command(c);
                                                           }));
  composition.add(flight);
  composition.add(*ios);  // starts the page
  int port = 0;
  std::ifstream(dir / "ios.port") >> port;
  ASSERT_GT(port, 0);
  composition.run(10);

  // The live fields come from the composition's topics (a few samples a second are kept: the
  // first of the run at least), the timing view from its frames.
  const auto [status, body] = http(port, "GET", "/api/state");
  ASSERT_EQ(status, 200) << body;
  const auto state = nlohmann::json::parse(body);
  EXPECT_TRUE(state["topics"].dump().find("altitude_msl_m") != std::string::npos) << state["topics"].dump();
  EXPECT_EQ(state["timing"]["frame"], 9);
  EXPECT_EQ(state["timing"]["run_state"], "run");

  const auto [accepted, reply] = http(port, "POST", "/api/command", R"({"command": "freeze"})");
  ASSERT_EQ(accepted, 200) << reply;
  EXPECT_TRUE(sent.empty()) << "sent from the frame thread, not the page's";
  composition.step_frame();  // the station writes it: every component has it next frame
  ASSERT_EQ(sent.size(), 1u);
  EXPECT_EQ(sent[0].kind(), msg::COMMAND_RUN_STATE);
  EXPECT_EQ(sent[0].issuer().to_string(), "ios");
  EXPECT_EQ(composition.step_frame().run_state, msg::RUN_STATE_FREEZE);
  EXPECT_EQ(composition.last_frame().dt_s, 0.0);

  composition.stop();
  EXPECT_EQ(http(port, "GET", "/api/state").first, 0) << "the page stops with the station";
  EXPECT_EQ(http(port, "POST", "/api/command", R"({"command": "run"})").first, 0);
}

}  // namespace
}  // namespace fedsim::ios
