#pragma once
// Transports of `clips serve`: HTTP (cpp-httplib) and JSON lines on stdin/stdout.
#include <iosfwd>
#include <string>
#include <vector>

#include "serve/service.hpp"

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

// Serves until SIGINT or SIGTERM, then lets in-flight requests finish and
// returns 0; returns kCannotListen when the address cannot be bound. Prints
// "clips serve: listening on http://HOST:PORT/" on `log` once ready.
// Call before starting other threads: it blocks SIGINT/SIGTERM in the caller
// so that every thread it starts inherits the mask.
int run_http(Service& service, const HttpOptions& options, std::ostream& log);

// One request per input line: {"method": "POST", "path": "/api/sessions",
// "body": {...}} (body optional); one reply per output line: {"status": 201,
// "body": {...}}. A line longer than the body limit and 4 KiB for the
// envelope is answered 413 unread. The caller of stdin is the owner (may
// list and delete every session). Returns 0 at end of input.
int run_stdio(Service& service, std::istream& in, std::ostream& out);

}  // namespace clips::serve
