// The station's server over real sockets on the loopback: the page, the API, the WebSocket push,
// and the refusals (a non-loopback bind without a token, a port in use, a missing page).
#include "ios/server/web_server.hpp"
#include "common/util/build_paths.hpp"

#include <civetweb.h>
#include <gtest/gtest.h>

#include <atomic>
#include <chrono>
#include <cstring>
#include <string>
#include <thread>

namespace fedsim::ios {
namespace {

/// A blocking HTTP/1.1 request through civetweb's client; returns "<status>\n<body>".
std::string http(int port, const std::string& method, const std::string& path, const std::string& body = {}) {
  char error[256] = "";
  mg_connection* conn = mg_connect_client("127.0.0.1", port, 0, error, sizeof error);
  if (!conn) return std::string("connect failed: ") + error;
  mg_printf(conn, "%s %s HTTP/1.1\r\nHost: 127.0.0.1\r\nContent-Length: %zu\r\nConnection: close\r\n\r\n",
            method.c_str(), path.c_str(), body.size());
  if (!body.empty()) mg_write(conn, body.data(), body.size());
  std::string out;
  if (mg_get_response(conn, error, sizeof error, 5000) >= 0) {
    out = std::to_string(mg_get_response_info(conn)->status_code) + "\n";
    char buf[4096];
    int n = 0;
    while ((n = mg_read(conn, buf, sizeof buf)) > 0) out.append(buf, static_cast<std::size_t>(n));
  } else {
    out = std::string("no response: ") + error;
  }
  mg_close_connection(conn);
  return out;
}

ServerOptions loopback_any_port() {
  ServerOptions o;
  o.port = 0;
  o.web_root = fedsim::util::source_dir() + "/federates/ios/web";
  return o;
}

TEST(WebServer, ServesThePageAndTheApiOnTheLoopback) {
  WebServer server(loopback_any_port());
  server.handle("POST", "/api/echo", [](const HttpRequest& r) {
    return HttpResponse{200, "application/json", "{\"got\":\"" + r.body + "\",\"x\":\"" + r.parameter("x") + "\"}"};
  });
  server.handle("GET", "/api/fail", [](const HttpRequest&) -> HttpResponse { throw std::runtime_error("broken \"on purpose\""); });
  server.start();
  ASSERT_GT(server.port(), 0);
  EXPECT_EQ(server.url(), "http://127.0.0.1:" + std::to_string(server.port()) + "/");
  const std::string page = http(server.port(), "GET", "/");
  EXPECT_EQ(page.substr(0, 4), "200\n");
  EXPECT_NE(page.find("<title>fedsim instructor station</title>"), std::string::npos);
  EXPECT_EQ(http(server.port(), "POST", "/api/echo?x=a%20b", "abc"), "200\n{\"got\":\"abc\",\"x\":\"a b\"}");
  // A handler's exception is the request's error, as JSON, and the server goes on.
  EXPECT_EQ(http(server.port(), "GET", "/api/fail"), "400\n{\"error\":\"broken \\\"on purpose\\\"\"}");
  // Only the page's own files: no path out of the web root, no unknown route.
  EXPECT_EQ(http(server.port(), "GET", "/../CMakeLists.txt").substr(0, 3), "404");
  EXPECT_EQ(http(server.port(), "GET", "/api/nothing").substr(0, 3), "404");
  EXPECT_EQ(http(server.port(), "GET", "/api/echo").substr(0, 3), "404");  // wrong method
  EXPECT_EQ(server.statistics().refused, 0u);
}

TEST(WebServer, PushesToEveryWebSocketClientAfterItsGreeting) {
  WebServer server(loopback_any_port());
  server.set_greeting([] { return std::string("hello"); });
  std::atomic<int> from_page{0};
  server.on_message([&](const std::string& m) { from_page += m == "ping"; });
  server.start();
  struct Received {
    std::mutex mutex;
    std::vector<std::string> messages;
  } received;
  char error[256] = "";
  mg_connection* ws = mg_connect_websocket_client(
      "127.0.0.1", server.port(), 0, error, sizeof error, "/ws", nullptr,
      [](mg_connection*, int bits, char* data, std::size_t size, void* user) {
        auto* r = static_cast<Received*>(user);
        if ((bits & 0x0f) == MG_WEBSOCKET_OPCODE_TEXT) {
          std::lock_guard lock(r->mutex);
          r->messages.emplace_back(data, size);
        }
        return 1;
      },
      nullptr, &received);
  ASSERT_NE(ws, nullptr) << error;
  const auto until = std::chrono::steady_clock::now() + std::chrono::seconds(5);
  while (server.statistics().clients < 1 && std::chrono::steady_clock::now() < until) {
    std::this_thread::sleep_for(std::chrono::milliseconds(5));
  }
  EXPECT_EQ(server.broadcast("state 1"), 1);
  EXPECT_EQ(server.broadcast("state 2"), 1);
  mg_websocket_client_write(ws, MG_WEBSOCKET_OPCODE_TEXT, "ping", 4);
  for (;;) {
    {
      std::lock_guard lock(received.mutex);
      if (received.messages.size() >= 3 && from_page.load() == 1) break;
    }
    ASSERT_LT(std::chrono::steady_clock::now(), until) << "pushes did not arrive";
    std::this_thread::sleep_for(std::chrono::milliseconds(5));
  }
  {
    std::lock_guard lock(received.mutex);
    EXPECT_EQ(received.messages, (std::vector<std::string>{"hello", "state 1", "state 2"}));
  }
  EXPECT_EQ(server.statistics().messages_sent, 2u);  // the greeting is not a push
  mg_close_connection(ws);
}

TEST(WebServer, RefusesToOpenBeyondThisMachineWithoutAToken) {
  ServerOptions o = loopback_any_port();
  o.bind_address = "0.0.0.0";
  WebServer open(o);
  try {
    open.start();
    FAIL() << "a public bind without a token started";
  } catch (const ServerError& e) {
    EXPECT_NE(std::string(e.what()).find("give an access token"), std::string::npos) << e.what();
  }
  // The negative control: with a token it listens.
  o.token = "0123456789abcdef-token";
  WebServer with_token(o);
  EXPECT_NO_THROW(with_token.start());
  EXPECT_EQ(http(with_token.port(), "GET", "/").substr(0, 3), "200");  // from the loopback: no token needed
}

TEST(WebServer, SaysWhyItCannotStart) {
  WebServer first(loopback_any_port());
  first.start();
  ServerOptions taken = loopback_any_port();
  taken.port = first.port();
  WebServer second(taken);
  EXPECT_THROW(second.start(), ServerError);
  ServerOptions no_page = loopback_any_port();
  no_page.web_root = "/nonexistent-fedsim-web-root";
  WebServer third(no_page);
  try {
    third.start();
    FAIL();
  } catch (const ServerError& e) {
    EXPECT_NE(std::string(e.what()).find("no index.html"), std::string::npos);
  }
}

}  // namespace
}  // namespace fedsim::ios
