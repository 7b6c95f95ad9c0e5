// fedsim-ios: the instructor station (seed node 4, Chapter 9) as a federate with a web page.
//
// Ports (DDS):
//   reads     every state topic of the catalogue (aircraft, engines, navigation, autopilot,
//             motion, control loading, visual status, pilot controls) with best-effort
//             keep-last-1 readers that never hold a frame back, fedsim/federate_status (the
//             federation panel), fedsim/visual_picture (the channels' live pictures),
//             fedsim/frame_tick (run state, sim time, mode) and fedsim/sim_command (the
//             settings in force, from the topic's transient-local history)
//   writes    fedsim/sim_command: what the instructor asks on the page
// Web (ios/server, 127.0.0.1 by default):
//   GET  /            the page (federates/ios/web)
//   WS   /ws          pushes of the whole live picture, push_hz times a second
//   GET  /api/state   the same picture once (JSON)
//   GET  /api/map     runways, ILS feathers and navaids around ?airport= (navigation database)
//   GET  /api/picture ?channel=<id>: the channel's newest JPEG
//   POST /api/command a command as JSON (common/instructor/request_json.hpp)
//   POST /api/replay  start (the ring's last N s, or a recording), pause, resume, seek, speed,
//                     take control (station_replay.hpp)
//   POST /api/scenario start a scenario file of --scenarios (common/scenario), or stop it; it
//                     runs on the frame thread: timed events on the tick's sim time, conditions
//                     on the field registry (a frame the registry is busy is caught up next frame)
//
// Threads: the frame thread only notes the tick; DDS listener threads flatten at most a few
// samples a second per topic into the field registry (ios/model/live_fields) under a mutex;
// one pusher thread builds and sends the pushes; civetweb's threads answer the page. Nothing
// the page does can block a frame.
#pragma once

#include "common/runtime/federate_options.hpp"
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

/// Runs the station until SIGINT/SIGTERM, a SHUTDOWN command or --duration. Exit codes as every
/// federate: 0 clean, 1 failed, 2 bad input (the server could not start, no database ...).
int run_station(const StationOptions& options);

}  // namespace fedsim::ios
