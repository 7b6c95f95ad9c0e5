// fedsim-ios: the instructor station (seed node 4, Chapter 9) as a component with a web page.
//
// Ports (--print-ports; fedsim graph draws them):
//   monitors  every state topic of the catalogue (aircraft, engines, navigation, autopilot,
//             motion, control loading, visual status; "state": best effort, keep last 1) and
//             fedsim/pilot_controls ("pilot_controls", its writer's exclusive ownership),
//             fedsim/visual_picture ("picture": the channels' live pictures) and
//             fedsim/federate_status ("status": the federation panel), each sample as it
//             arrives (a few a second kept); as monitors they never hold a frame back
//   writes    fedsim/sim_command: what the instructor asks on the page (sent from the frame
//             thread, the frame after it was asked)
//             fedsim/replay_state: a replay's states (station_replay.hpp; over DDS only)
//   and as every component: the tick (run state, sim time, mode: the station's step) and the
//   commands (on_command: the settings in force, from the topic's transient-local history).
// Web (ios/server, 127.0.0.1 by default), served from on_start() to on_stop():
//   GET  /            the page (federates/ios/web)
//   WS   /ws          pushes of the whole live picture, push_hz times a second
//   GET  /api/state   the same picture once (JSON)
//   GET  /api/map     runways, ILS feathers and navaids around ?airport= (navigation database)
//   GET  /api/picture ?channel=<id>: the channel's newest JPEG
//   POST /api/command a command as JSON (common/instructor/request_json.hpp)
//   POST /api/replay  start (the ring's last N s, or a recording), pause, resume, seek, speed,
//                     take control (station_replay.hpp; over DDS only: 503 in-process)
//   POST /api/scenario start a scenario file of --scenarios (common/scenario), or stop it; it
//                     runs on the frame thread: timed events on the tick's sim time, conditions
//                     on the field registry (a frame the registry is busy is caught up next frame)
//
// Hosts: over DDS (fedsim-ios, main.cpp) and in `fedsim run --in-process`, where the page shows
// the composition's topics and its commands go into the composition (docs/architecture.md says
// what needs a live federation).
//
// Threads: the frame thread notes the tick and sends the page's commands; the host's threads
// (DDS listeners, or the composition's) flatten at most a few samples a second per topic into
// the field registry (ios/model/live_fields) under a mutex; one pusher thread builds and sends
// the pushes; civetweb's threads answer the page. Nothing the page does can block a frame.
#pragma once

#include "common/runtime/federate_main.hpp"
#include "ios/server/web_server.hpp"

#include <string>

namespace fedsim::ios {

struct StationOptions {
  runtime::FederateOptions federate;
  ServerOptions server;
  std::string port_file;        // written with the port once listening ("" = none)
  double push_hz = 15.0;        // pushes to the page per second
  std::string airport = "KSFO"; // the map's airport at start
  double map_radius_nm = 40.0;  // navaids shown within this radius of it
  std::string navdb_file;       // "" = the built database
  double ring_minutes = 10.0;   // live aircraft state kept for "replay the last N minutes"
  std::string recordings = "out";  // folders (fedsim record / fedsim run --out) the page may replay
  std::string scenarios;        // scenario files the page may run ("" = data/scenarios)
};

/// fedsim-ios's options and component (main.cpp, fedsim run --in-process, fedsim graph). Exit
/// codes as every federate: 0 clean, 1 failed, 2 bad input (a public address without a token,
/// the server could not start, no database...).
runtime::FederateProgram program();

}  // namespace fedsim::ios
