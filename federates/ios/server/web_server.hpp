// The instructor station's HTTP + WebSocket server: civetweb (Debian's libcivetweb, an embedded
// server with WebSockets built in) behind a small interface, so that the station's adapter never
// sees a socket and this layer never sees DDS.
//
//   - Static files: every plain file directly in `web_root` (names of [A-Za-z0-9._-]), read at
//     start; "/" is index.html. Nothing else on disk is reachable.
//   - API: handlers registered by method and exact path ("GET /api/map"), called on civetweb's
//     worker threads (so a handler must be thread-safe and quick).
//   - WebSocket "/ws": broadcast() sends one text message to every open connection; a new
//     connection first gets greeting() (so a page has the whole picture at once).
//   - Access: ios/model/access_policy on every request and WebSocket upgrade; refused requests
//     are answered 403 and counted.
// Throws ServerError when it cannot listen (address in use, bad address, no token for a
// non-loopback address, no index.html).
#pragma once

#include <atomic>
#include <cstdint>
#include <functional>
#include <map>
#include <memory>
#include <mutex>
#include <set>
#include <stdexcept>
#include <string>

struct mg_context;
struct mg_connection;

namespace fedsim::ios {

class ServerError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

struct ServerOptions {
  std::string bind_address = "127.0.0.1";
  int port = 8470;         // 0: any free port (port() tells which)
  std::string web_root;    // folder of the page's files
  std::string token;       // access token for non-loopback clients ("" = loopback only)
  int threads = 6;         // civetweb worker threads (each open WebSocket holds one)
};

struct HttpRequest {
  std::string method;
  std::string path;
  std::string query;
  std::string body;
  std::string remote_address;
  /// The query parameter `key` ("" if absent; no URL decoding beyond %xx and '+').
  std::string parameter(const std::string& key) const;
};

struct HttpResponse {
  int status = 200;
  std::string content_type = "application/json";
  std::string body;
};

struct ServerStatistics {
  std::uint64_t requests = 0;
  std::uint64_t refused = 0;          // access policy said no
  std::uint64_t messages_sent = 0;    // WebSocket messages (one per client)
  std::uint64_t bytes_sent = 0;       // WebSocket payload bytes
  std::uint64_t clients = 0;          // open WebSocket connections now
};

class WebServer {
 public:
  using Handler = std::function<HttpResponse(const HttpRequest&)>;

  explicit WebServer(ServerOptions options);
  ~WebServer();
  WebServer(const WebServer&) = delete;
  WebServer& operator=(const WebServer&) = delete;

  /// Registers `handler` for `method` and exact `path` (call before start()).
  void handle(const std::string& method, const std::string& path, Handler handler);
  /// The message a new WebSocket connection receives first (call before start()).
  void set_greeting(std::function<std::string()> greeting) { greeting_ = std::move(greeting); }
  /// Called with each text message a page sends on the WebSocket (call before start()).
  void on_message(std::function<void(const std::string&)> handler) { on_message_ = std::move(handler); }

  /// Starts listening; throws ServerError.
  void start();
  /// Stops listening and closes every connection (also done by the destructor).
  void stop();

  int port() const { return port_; }
  /// "http://127.0.0.1:8470/"
  std::string url() const;

  /// Sends `text` to every open WebSocket connection; returns how many got it.
  int broadcast(const std::string& text);
  ServerStatistics statistics() const;

 private:
  static int on_request(mg_connection* conn, void* self);
  static int on_ws_connect(const mg_connection* conn, void* self);
  static void on_ws_ready(mg_connection* conn, void* self);
  static int on_ws_data(mg_connection* conn, int bits, char* data, std::size_t size, void* self);
  static void on_ws_close(const mg_connection* conn, void* self);
  bool allowed(const mg_connection* conn);
  void load_static_files();

  ServerOptions options_;
  mg_context* context_ = nullptr;
  int port_ = 0;
  std::map<std::string, Handler> handlers_;              // "GET /api/map"
  std::map<std::string, std::string> files_;             // "/ios.js" -> content
  std::function<std::string()> greeting_;
  std::function<void(const std::string&)> on_message_;
  mutable std::mutex clients_mutex_;
  std::set<mg_connection*> clients_;
  std::atomic<std::uint64_t> requests_{0}, refused_{0}, messages_{0}, bytes_{0};
};

/// The MIME type served for a file name ("application/octet-stream" if unknown).
std::string content_type_for(const std::string& file_name);

}  // namespace fedsim::ios
