#pragma once
// The boundary between `clips serve` and its HTTP transport, which lives in
// a module of its own (src/serve/http/, built as clips-http.so) so that only
// a call that serves over HTTP loads cpp-httplib and OpenSSL. Both sides see
// these plain types only; the module calls back into the service through
// HttpHost.
#include <cstddef>
#include <functional>
#include <iosfwd>
#include <string>
#include <vector>

#include "serve/messages.hpp"

namespace clips::serve {

struct HttpOptions {
  std::string host = "127.0.0.1";
  int port = 8080;  // 0: any free port (the printed URL says which)
  int threads = 8;  // session requests handled at once (health, catalogue and page never wait for them)
  // A connection carries one request, which must arrive in full (head and
  // body) within this many seconds of the connection; its reply must be
  // written within as many again.
  double read_timeout = 10;
  int max_connections = 128;        // open at once; more: 503 and closed
  int max_client_connections = 64;  // open at once from one address
  std::vector<std::string> allow_origins;  // cross-origin pages allowed besides loopback ones ("*": any)
  std::string owner_token;          // "Authorization: Bearer TOKEN" lists and deletes every session
};

// The listen backlog (cpp-httplib's own is 5).
inline constexpr int kListenBacklog = 256;

// What run_http returns when it cannot listen (the port is taken, or the
// address cannot be bound); `clips serve` exits with its own code then.
inline constexpr int kCannotListen = -1;

// What the transport needs of the service.
struct HttpHost {
  std::function<Reply(const Request&)> handle;  // thread-safe
  std::function<void()> expire_idle;            // called about once a second
  std::function<std::string(const std::string& path)> allowed_methods;  // Service::allowed_methods
  size_t max_body_bytes = 0;
  std::string program_name;                     // for its messages ("clips")
};

// The module's one entry point, run_http's contract (frontends.hpp).
using HttpServeFunction = int (*)(const HttpHost&, const HttpOptions&, std::ostream&);
inline constexpr const char* kHttpServeSymbol = "clips_http_serve";
inline constexpr const char* kHttpModuleName = "clips-http.so";

}  // namespace clips::serve

extern "C" int clips_http_serve(const clips::serve::HttpHost& host, const clips::serve::HttpOptions& options,
                                std::ostream& log);
