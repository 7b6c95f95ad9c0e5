#include "ios/model/access_policy.hpp"

#include <arpa/inet.h>

#include <cstring>

namespace fedsim::ios {

namespace {

/// The value of `key` in "a=1&key=v" or "a=1; key=v" (separator `sep`), "" if absent.
std::string field_value(const std::string& text, const std::string& key, char sep) {
  std::size_t pos = 0;
  while (pos <= text.size()) {
    std::size_t end = text.find(sep, pos);
    if (end == std::string::npos) end = text.size();
    std::string item = text.substr(pos, end - pos);
    item.erase(0, item.find_first_not_of(' '));
    if (item.compare(0, key.size() + 1, key + "=") == 0) return item.substr(key.size() + 1);
    pos = end + 1;
  }
  return {};
}

/// Compares in time independent of where the strings differ (no timing oracle for the token).
bool same_secret(const std::string& a, const std::string& b) {
  if (a.size() != b.size()) return false;
  unsigned char diff = 0;
  for (std::size_t i = 0; i < a.size(); ++i) diff |= static_cast<unsigned char>(a[i] ^ b[i]);
  return diff == 0;
}

}  // namespace

bool is_loopback_address(const std::string& address) {
  in_addr v4{};
  if (inet_pton(AF_INET, address.c_str(), &v4) == 1) {
    return (ntohl(v4.s_addr) >> 24) == 127;
  }
  in6_addr v6{};
  if (inet_pton(AF_INET6, address.c_str(), &v6) == 1) {
    static const unsigned char kLoopback[16] = {0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 1};
    if (std::memcmp(v6.s6_addr, kLoopback, 16) == 0) return true;
    static const unsigned char kMapped[12] = {0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0xff, 0xff};
    return std::memcmp(v6.s6_addr, kMapped, 12) == 0 && v6.s6_addr[12] == 127;
  }
  return false;
}

std::string bind_problem(const std::string& bind_address, const std::string& token) {
  in_addr v4{};
  in6_addr v6{};
  if (inet_pton(AF_INET, bind_address.c_str(), &v4) != 1 && inet_pton(AF_INET6, bind_address.c_str(), &v6) != 1) {
    return "--bind '" + bind_address + "' is not an IPv4 or IPv6 address";
  }
  if (!token.empty() && token.size() < kMinTokenLength) {
    return "the access token has " + std::to_string(token.size()) + " characters; use at least " +
           std::to_string(kMinTokenLength);
  }
  if (!is_loopback_address(bind_address) && token.empty()) {
    return "--bind " + bind_address + " opens the instructor station beyond this machine: give an access "
           "token (--token-file FILE or FEDSIM_IOS_TOKEN), or bind to 127.0.0.1";
  }
  return {};
}

bool request_allowed(const std::string& remote_address, const std::string& presented,
                     const std::string& configured_token) {
  if (is_loopback_address(remote_address)) return true;
  return !configured_token.empty() && same_secret(presented, configured_token);
}

std::string presented_token(const std::string& authorization_header, const std::string& query,
                            const std::string& cookie_header) {
  const std::string bearer = "Bearer ";
  if (authorization_header.compare(0, bearer.size(), bearer) == 0) return authorization_header.substr(bearer.size());
  std::string t = field_value(query, "token", '&');
  if (!t.empty()) return t;
  return field_value(cookie_header, "fedsim_token", ';');
}

}  // namespace fedsim::ios
