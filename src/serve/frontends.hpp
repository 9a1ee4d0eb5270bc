#pragma once
// Transports of `clips serve`: HTTP (cpp-httplib) and JSON lines on stdin/stdout.
#include <iosfwd>
#include <string>
#include <vector>

#include "serve/http_server.hpp"
#include "serve/service.hpp"

namespace clips::serve {

// Serves until SIGINT or SIGTERM, then lets in-flight requests finish and
// returns 0; returns kCannotListen when the address cannot be bound. Prints
// "clips serve: listening on http://HOST:PORT/" on `log` once ready.
// Call before starting other threads: it blocks SIGINT/SIGTERM in the caller
// so that every thread it starts inherits the mask.
// The transport is the module clips-http.so (http_server.hpp), loaded on
// first use; a missing module throws util::SharedLibraryError naming where
// it was looked for.
int run_http(Service& service, const HttpOptions& options, std::ostream& log);

// Loads the HTTP module now, so that a missing one is reported before the
// datasets are read (throws as run_http does).
void load_http_module();

// One request per input line: {"method": "POST", "path": "/api/sessions",
// "body": {...}} (body optional); one reply per output line: {"status": 201,
// "body": {...}}. A line longer than the body limit and 4 KiB for the
// envelope is answered 413 unread. The caller of stdin is the owner (may
// list and delete every session). Returns 0 at end of input.
int run_stdio(Service& service, std::istream& in, std::ostream& out);

}  // namespace clips::serve
