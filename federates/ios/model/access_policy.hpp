// Who may use the instructor station (seed 9.4: the instructor controls the whole simulator, so
// the station is not open to the network by default).
//   - It binds to 127.0.0.1 unless told otherwise; binding to any other address needs an access
//     token (at least 16 characters), or it refuses to start.
//   - A client on the loopback (127.0.0.0/8, ::1) is served; any other client must present the
//     token: header "Authorization: Bearer <token>", a "token=<token>" query parameter, or the
//     cookie "fedsim_token" the page sets from it.
#pragma once

#include <string>

namespace fedsim::ios {

inline constexpr std::size_t kMinTokenLength = 16;

/// True for 127.0.0.0/8, ::1 and IPv4-mapped loopback (::ffff:127.x.y.z).
bool is_loopback_address(const std::string& address);

/// "" if the station may listen on `bind_address` with `token` (empty: none configured);
/// otherwise why not, naming the option to fix it.
std::string bind_problem(const std::string& bind_address, const std::string& token);

/// Whether a request from `remote_address` presenting `presented` (empty: none) is served.
bool request_allowed(const std::string& remote_address, const std::string& presented,
                     const std::string& configured_token);

/// The token a request presents: the Authorization header's bearer token, else the "token"
/// query parameter, else the "fedsim_token" cookie ("" if none).
std::string presented_token(const std::string& authorization_header, const std::string& query,
                            const std::string& cookie_header);

}  // namespace fedsim::ios
