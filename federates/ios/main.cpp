// fedsim-ios: the instructor station. See ios_station.hpp.
#include "ios/ios_station.hpp"
#include "common/util/build_paths.hpp"

#include "common/runtime/federate_main.hpp"
#include "common/util/cli_checks.hpp"

#include <CLI/CLI.hpp>

#include <cstdlib>
#include <fstream>
#include <iostream>

namespace {

/// The token from a file (first line) or FEDSIM_IOS_TOKEN; never from the command line, where
/// every user of the machine can read it (ps).
std::string read_token(const std::string& token_file) {
  if (!token_file.empty()) {
    std::ifstream in(token_file);
    if (!in) throw std::runtime_error("--token-file " + token_file + ": cannot read it");
    std::string token;
    std::getline(in, token);
    while (!token.empty() && (token.back() == '\r' || token.back() == ' ')) token.pop_back();
    if (token.empty()) throw std::runtime_error("--token-file " + token_file + ": the first line is empty");
    return token;
  }
  const char* env = std::getenv("FEDSIM_IOS_TOKEN");
  return env ? env : "";
}

}  // namespace

int main(int argc, char** argv) {
  using namespace fedsim;
  ios::StationOptions o;
  o.server.web_root = fedsim::util::source_dir() + "/federates/ios/web";
  std::string token_file;
  CLI::App app{"fedsim-ios: the instructor station: a web page (map, plots, instruments, channel "
               "pictures, federation, commands) served on 127.0.0.1"};
  runtime::add_federate_options(app, o.federate, "ios");
  app.add_option("--http-port", o.server.port, "TCP port of the page (0 = any free port; default FEDSIM_IOS_PORT or 8470)")
      ->check(util::FiniteRange(0, 65535))
      ->capture_default_str();
  app.add_option("--bind", o.server.bind_address,
                 "address to listen on; anything but loopback needs --token-file or FEDSIM_IOS_TOKEN")
      ->capture_default_str();
  app.add_option("--token-file", token_file, "file whose first line is the access token (>= 16 characters)");
  app.add_option("--port-file", o.port_file, "write the port to this file once listening");
  app.add_option("--push-hz", o.push_hz, "pushes of the live state to the page per second")
      ->check(util::FiniteRange(1.0, 60.0))
      ->capture_default_str();
  app.add_option("--airport", o.airport, "the map's airport (ICAO ident)")->capture_default_str();
  app.add_option("--map-radius-nm", o.map_radius_nm, "navaids within this distance of the airport [NM]")
      ->check(util::FiniteRange(1.0, 200.0))
      ->capture_default_str();
  app.add_option("--ring-minutes", o.ring_minutes, "live aircraft state kept for replay [min]")
      ->check(util::FiniteRange(0.5, 120.0))
      ->capture_default_str();
  app.add_option("--recordings", o.recordings, "folder of recordings the page may replay (fedsim record / fedsim run --out)")
      ->capture_default_str();
  app.add_option("--scenarios", o.scenarios, "folder of scenario files the page may run (default: data/scenarios)");
  app.add_option("--navdb", o.navdb_file, "navigation database (default: the one the build made)");
  app.add_option("--web-root", o.server.web_root, "folder of the page's files")->capture_default_str();
  try {
    // FEDSIM_IOS_PORT gives the default port (as FEDSIM_DOMAIN gives the domain): a deployment
    // run by a test takes any free port without editing the file.
    if (const char* env = std::getenv("FEDSIM_IOS_PORT")) {
      char* end = nullptr;
      const long port = std::strtol(env, &end, 10);
      if (end == env || *end != '\0' || port < 0 || port > 65535) {
        throw std::runtime_error(std::string("FEDSIM_IOS_PORT '") + env + "' is not a port number (0..65535)");
      }
      o.server.port = static_cast<int>(port);
    }
    app.parse(argc, argv);
    o.server.token = read_token(token_file);
  } catch (const CLI::ParseError& e) {
    return app.exit(e) == 0 ? runtime::kExitOk : runtime::kExitBadInput;
  } catch (const std::exception& e) {
    std::cerr << "fedsim-ios: " << e.what() << "\n";
    return runtime::kExitBadInput;
  }
  return ios::run_station(o);
}
