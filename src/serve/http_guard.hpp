#pragma once
// The checks `clips serve` makes on a request's head (request line and
// headers) before cpp-httplib reads the rest: sizes (414/431), the Host and
// Origin a browser sent (DNS rebinding, other web pages: 403), the method
// (405 with Allow, OPTIONS), and what a POST must declare (411/413/415).
// Pure functions of the bytes received, so tests and fuzzers call them
// without a socket; src/serve/frontends.cpp applies them per connection.
#include <functional>
#include <optional>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "serve/messages.hpp"

namespace clips::serve {

// Limits of a request head. The request line and each header line stay
// below cpp-httplib's own limits (8192 bytes each).
inline constexpr size_t kMaxRequestLine = 8000;
inline constexpr size_t kMaxHeaderLine = 8000;
inline constexpr size_t kMaxHead = 16384;  // request line and every header

struct RequestHead {
  std::string method, target, version;
  std::vector<std::pair<std::string, std::string>> headers;  // names lower-cased, values trimmed
  // The value of the first header of that (lower-case) name, or null.
  const std::string* header(std::string_view name) const;
};

enum class HeadScan {
  incomplete,        // no blank line yet, and still within the limits
  complete,          // `head` is filled; `head_bytes` long, the body follows
  request_line_too_long,  // 414
  too_large,         // 431: a header line or the whole head is over its limit
  malformed,         // 400
};

// Reads the head from the bytes received so far.
HeadScan scan_head(std::string_view received, RequestHead& head, size_t& head_bytes);

struct GuardPolicy {
  std::string listen_host;                // --host
  std::vector<std::string> allow_origins;  // --allow-origin ("*": any)
  size_t max_body_bytes = 64 * 1024;
  // The methods a path answers ("GET, HEAD"; "" for no such path):
  // Service::allowed_methods.
  std::function<std::string(const std::string& path)> allowed_methods;
};

// The Host header's name without its port, lower-cased ("[::1]" keeps its brackets).
std::string host_name(std::string_view host_header);
// Whether a request naming this Host may be served: IP literals, localhost
// and *.localhost, the --host name and the hosts of the allowed origins.
// Other names are what a DNS-rebinding page sends.
bool host_allowed(std::string_view host_header, const GuardPolicy& policy);

enum class OriginVerdict { none, same, allowed_cross, refused };
// The Origin header against the Host: absent (not a browser's cross-origin
// request), the page's own origin, a loopback origin (any port) or one of
// --allow-origin (a cross-origin caller that gets CORS headers), or refused.
OriginVerdict check_origin(const RequestHead& head, const GuardPolicy& policy);

// The reply a request gets without reaching the handlers, or nothing when it
// may go on. The Allow list of a path comes from policy.allowed_methods.
std::optional<Reply> screen_request(const RequestHead& head, const GuardPolicy& policy);

// A complete HTTP/1.1 response (with "Connection: close") for `reply`.
std::string format_response(const Reply& reply, bool head_only = false);

}  // namespace clips::serve
