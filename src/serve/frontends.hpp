#pragma once
// Transports of `clips serve`: HTTP (cpp-httplib) and JSON lines on stdin/stdout.
#include <iosfwd>
#include <string>

#include "serve/service.hpp"

namespace clips::serve {

struct HttpOptions {
  std::string host = "127.0.0.1";
  int port = 8080;  // 0: any free port (the printed URL says which)
  int threads = 8;  // requests served at once
};

// Serves until SIGINT or SIGTERM, then lets in-flight requests finish and
// returns 0; returns 1 when the address cannot be bound. Prints
// "clips serve: listening on http://HOST:PORT/" on `log` once ready.
// Call before starting other threads: it blocks SIGINT/SIGTERM in the caller
// so that every thread it starts inherits the mask.
int run_http(Service& service, const HttpOptions& options, std::ostream& log);

// One request per input line: {"method": "POST", "path": "/api/sessions",
// "body": {...}} (body optional); one reply per output line: {"status": 201,
// "body": {...}}. Returns 0 at end of input.
int run_stdio(Service& service, std::istream& in, std::ostream& out);

}  // namespace clips::serve
