#include "ios/server/web_server.hpp"

#include "ios/model/access_policy.hpp"

#include <civetweb.h>
#include <nlohmann/json.hpp>

#include <cctype>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <vector>

namespace fedsim::ios {

namespace {

std::string header(const mg_connection* conn, const char* name) {
  const char* v = mg_get_header(conn, name);
  return v ? v : "";
}

std::string percent_decoded(const std::string& text) {
  std::string out;
  for (std::size_t i = 0; i < text.size(); ++i) {
    if (text[i] == '+') {
      out += ' ';
    } else if (text[i] == '%' && i + 2 < text.size() && std::isxdigit(static_cast<unsigned char>(text[i + 1])) &&
               std::isxdigit(static_cast<unsigned char>(text[i + 2]))) {
      out += static_cast<char>(std::stoi(text.substr(i + 1, 2), nullptr, 16));
      i += 2;
    } else {
      out += text[i];
    }
  }
  return out;
}

const char* reason_phrase(int status) {
  switch (status) {
    case 200: return "OK";
    case 400: return "Bad Request";
    case 403: return "Forbidden";
    case 404: return "Not Found";
    case 405: return "Method Not Allowed";
    case 413: return "Payload Too Large";
    case 503: return "Service Unavailable";
    default: return "Error";
  }
}

void send_response(mg_connection* conn, const HttpResponse& r) {
  mg_printf(conn,
            "HTTP/1.1 %d %s\r\nContent-Type: %s\r\nContent-Length: %zu\r\nCache-Control: no-store\r\n"
            "X-Content-Type-Options: nosniff\r\nConnection: close\r\n\r\n",
            r.status, reason_phrase(r.status), r.content_type.c_str(), r.body.size());
  if (!r.body.empty()) mg_write(conn, r.body.data(), r.body.size());
}

constexpr std::size_t kMaxBodyBytes = 64 * 1024;  // a command is a few hundred bytes

}  // namespace

std::string HttpRequest::parameter(const std::string& key) const {
  std::size_t pos = 0;
  while (pos <= query.size()) {
    std::size_t end = query.find('&', pos);
    if (end == std::string::npos) end = query.size();
    const std::string item = query.substr(pos, end - pos);
    if (item.compare(0, key.size() + 1, key + "=") == 0) return percent_decoded(item.substr(key.size() + 1));
    pos = end + 1;
  }
  return {};
}

std::string content_type_for(const std::string& name) {
  const std::string ext = std::filesystem::path(name).extension().string();
  if (ext == ".html") return "text/html; charset=utf-8";
  if (ext == ".js" || ext == ".mjs") return "text/javascript; charset=utf-8";
  if (ext == ".css") return "text/css; charset=utf-8";
  if (ext == ".json") return "application/json";
  if (ext == ".png") return "image/png";
  if (ext == ".svg") return "image/svg+xml";
  if (ext == ".jpg" || ext == ".jpeg") return "image/jpeg";
  return "application/octet-stream";
}

WebServer::WebServer(ServerOptions options) : options_(std::move(options)) {}

WebServer::~WebServer() { stop(); }

void WebServer::handle(const std::string& method, const std::string& path, Handler handler) {
  handlers_[method + " " + path] = std::move(handler);
}

void WebServer::load_static_files() {
  namespace fs = std::filesystem;
  if (!fs::is_regular_file(fs::path(options_.web_root) / "index.html")) {
    throw ServerError("the instructor station's page is missing: no index.html in '" + options_.web_root +
                      "' (--web-root)");
  }
  for (const auto& entry : fs::directory_iterator(options_.web_root)) {
    const std::string name = entry.path().filename().string();
    if (!entry.is_regular_file() ||
        name.find_first_not_of("abcdefghijklmnopqrstuvwxyzABCDEFGHIJKLMNOPQRSTUVWXYZ0123456789._-") != std::string::npos) {
      continue;
    }
    std::ifstream in(entry.path(), std::ios::binary);
    std::ostringstream text;
    text << in.rdbuf();
    files_["/" + name] = text.str();
  }
  files_["/"] = files_["/index.html"];
}

void WebServer::start() {
  if (const std::string problem = bind_problem(options_.bind_address, options_.token); !problem.empty()) {
    throw ServerError(problem);
  }
  if (options_.port < 0 || options_.port > 65535) {
    throw ServerError("--http-port " + std::to_string(options_.port) + " is outside 0..65535");
  }
  load_static_files();
  mg_init_library(0);
  const bool v6 = options_.bind_address.find(':') != std::string::npos;
  const std::string listen = (v6 ? "[" + options_.bind_address + "]" : options_.bind_address) + ":" +
                             std::to_string(options_.port);
  const std::string threads = std::to_string(options_.threads);
  const char* civet_options[] = {"listening_ports", listen.c_str(), "num_threads", threads.c_str(),
                                 "enable_keep_alive", "no", "websocket_timeout_ms", "3600000", nullptr};
  mg_callbacks callbacks{};
  // civetweb prints its own errors to stderr; they are reported through ServerError instead.
  callbacks.log_message = [](const mg_connection*, const char*) { return 1; };
  context_ = mg_start(&callbacks, this, civet_options);
  if (!context_) {
    throw ServerError("cannot listen on " + listen + " (address in use, or not an address of this machine)");
  }
  mg_server_port ports[4];
  const int n = mg_get_server_ports(context_, 4, ports);
  port_ = n > 0 ? ports[0].port : options_.port;
  mg_set_request_handler(context_, "/", &WebServer::on_request, this);
  mg_set_websocket_handler(context_, "/ws", &WebServer::on_ws_connect, &WebServer::on_ws_ready,
                           &WebServer::on_ws_data, &WebServer::on_ws_close, this);
}

void WebServer::stop() {
  if (!context_) return;
  mg_stop(context_);  // closes every connection and joins civetweb's threads
  context_ = nullptr;
  std::lock_guard lock(clients_mutex_);
  clients_.clear();
}

std::string WebServer::url() const {
  const bool v6 = options_.bind_address.find(':') != std::string::npos;
  return "http://" + (v6 ? "[" + options_.bind_address + "]" : options_.bind_address) + ":" +
         std::to_string(port_) + "/";
}

bool WebServer::allowed(const mg_connection* conn) {
  const mg_request_info* info = mg_get_request_info(conn);
  const std::string token = presented_token(header(conn, "Authorization"),
                                            info->query_string ? info->query_string : "", header(conn, "Cookie"));
  if (request_allowed(info->remote_addr, token, options_.token)) return true;
  ++refused_;
  return false;
}

int WebServer::on_request(mg_connection* conn, void* self_ptr) {
  auto* self = static_cast<WebServer*>(self_ptr);
  ++self->requests_;
  const mg_request_info* info = mg_get_request_info(conn);
  if (!self->allowed(conn)) {
    send_response(conn, {403, "text/plain", "fedsim instructor station: this address needs the access token\n"});
    return 403;
  }
  HttpRequest request;
  request.method = info->request_method ? info->request_method : "";
  request.path = info->local_uri ? info->local_uri : "/";
  request.query = info->query_string ? info->query_string : "";
  request.remote_address = info->remote_addr;
  if (info->content_length > static_cast<long long>(kMaxBodyBytes)) {
    send_response(conn, {413, "application/json", R"({"error":"request body over 64 KiB"})"});
    return 413;
  }
  if (info->content_length > 0) {
    request.body.resize(static_cast<std::size_t>(info->content_length));
    const int got = mg_read(conn, request.body.data(), request.body.size());
    request.body.resize(got > 0 ? static_cast<std::size_t>(got) : 0);
  }
  HttpResponse response;
  if (auto it = self->handlers_.find(request.method + " " + request.path); it != self->handlers_.end()) {
    try {
      response = it->second(request);
    } catch (const std::exception& e) {
      response = {400, "application/json", nlohmann::json{{"error", e.what()}}.dump()};
    }
  } else if (auto file = self->files_.find(request.path); file != self->files_.end() && request.method == "GET") {
    response = {200, content_type_for(request.path == "/" ? "index.html" : request.path), file->second};
  } else {
    response = {404, "text/plain", "not found: " + request.path + "\n"};
  }
  send_response(conn, response);
  return response.status;
}

int WebServer::on_ws_connect(const mg_connection* conn, void* self_ptr) {
  auto* self = static_cast<WebServer*>(self_ptr);
  return self->allowed(conn) ? 0 : 1;  // non-zero refuses the upgrade
}

void WebServer::on_ws_ready(mg_connection* conn, void* self_ptr) {
  auto* self = static_cast<WebServer*>(self_ptr);
  // The greeting is built before clients_mutex_ is taken: the greeting may take the host's own
  // locks, and the host takes them before statistics() takes clients_mutex_ (one lock order).
  const std::string hello = self->greeting_ ? self->greeting_() : std::string();
  std::lock_guard lock(self->clients_mutex_);
  if (!hello.empty()) mg_websocket_write(conn, MG_WEBSOCKET_OPCODE_TEXT, hello.data(), hello.size());
  self->clients_.insert(conn);
}

int WebServer::on_ws_data(mg_connection*, int bits, char* data, std::size_t size, void* self_ptr) {
  auto* self = static_cast<WebServer*>(self_ptr);
  const int opcode = bits & 0x0f;
  if (opcode == MG_WEBSOCKET_OPCODE_CONNECTION_CLOSE) return 0;
  if (opcode == MG_WEBSOCKET_OPCODE_TEXT && self->on_message_) self->on_message_(std::string(data, size));
  return 1;  // keep the connection open
}

void WebServer::on_ws_close(const mg_connection* conn, void* self_ptr) {
  auto* self = static_cast<WebServer*>(self_ptr);
  std::lock_guard lock(self->clients_mutex_);
  self->clients_.erase(const_cast<mg_connection*>(conn));
}

int WebServer::broadcast(const std::string& text) {
  std::lock_guard lock(clients_mutex_);
  int sent = 0;
  for (mg_connection* conn : clients_) {
    if (mg_websocket_write(conn, MG_WEBSOCKET_OPCODE_TEXT, text.data(), text.size()) > 0) {
      ++sent;
      ++messages_;
      bytes_ += text.size();
    }
  }
  return sent;
}

ServerStatistics WebServer::statistics() const {
  ServerStatistics s;
  s.requests = requests_.load();
  s.refused = refused_.load();
  s.messages_sent = messages_.load();
  s.bytes_sent = bytes_.load();
  std::lock_guard lock(clients_mutex_);
  s.clients = clients_.size();
  return s;
}

}  // namespace fedsim::ios
