#include "serve/frontends.hpp"

#include <iostream>
#include <memory>
#include <mutex>
#include <nlohmann/json.hpp>

#include "util/program_name.hpp"
#include "util/shared_library.hpp"

// Where the HTTP module is installed, relative to the executable's folder and
// absolute (CMakeLists.txt sets both from the install layout).
#ifndef CLIPS_HTTP_MODULE_FROM_BINDIR
#define CLIPS_HTTP_MODULE_FROM_BINDIR "../lib/clips-assist"
#endif
#ifndef CLIPS_HTTP_MODULE_INSTALLED_DIR
#define CLIPS_HTTP_MODULE_INSTALLED_DIR "/usr/local/lib/clips-assist"
#endif

namespace clips::serve {

namespace {

// The module beside a build tree's executable (build/lib/clips-assist/), the
// one installed with it, then the installed path itself.
const util::SharedLibrary& http_module() {
  static std::unique_ptr<util::SharedLibrary> module;
  static std::mutex m;
  std::lock_guard lock(m);
  if (!module) {
    const std::string exe = util::executable_dir();
    std::vector<std::string> candidates;
    if (!exe.empty()) {
      candidates.push_back(exe + "/lib/clips-assist/" + kHttpModuleName);
      candidates.push_back(exe + "/" CLIPS_HTTP_MODULE_FROM_BINDIR "/" + kHttpModuleName);
    }
    candidates.push_back(std::string(CLIPS_HTTP_MODULE_INSTALLED_DIR "/") + kHttpModuleName);
    module = std::make_unique<util::SharedLibrary>(
        candidates, "the HTTP server is a module installed with " + util::program_name() +
                        " (`make build` builds it; `" + util::program_name() + " serve --stdio` needs none)");
  }
  return *module;
}

}  // namespace

void load_http_module() { http_module(); }

int run_http(Service& service, const HttpOptions& options, std::ostream& log) {
  const auto serve = http_module().function<HttpServeFunction>(kHttpServeSymbol);
  HttpHost host;
  host.handle = [&service](const Request& r) { return service.handle(r); };
  host.expire_idle = [&service] { service.expire_idle(); };
  host.allowed_methods = &Service::allowed_methods;
  host.max_body_bytes = service.limits().max_body_bytes;
  host.program_name = util::program_name();
  return serve(host, options, log);
}

namespace {

// One line of `in` into `line`, at most `max` bytes; false at end of input.
// A longer line is read to its end and dropped (`too_long` set).
bool read_line(std::istream& in, std::string& line, size_t max, bool& too_long) {
  line.clear();
  too_long = false;
  std::streambuf* buf = in.rdbuf();
  bool any = false;
  for (;;) {
    const int c = buf->sbumpc();
    if (c == std::char_traits<char>::eof()) {
      in.setstate(std::ios::eofbit);
      return any;
    }
    any = true;
    if (c == '\n') return true;
    if (line.size() < max) line.push_back(static_cast<char>(c));
    else too_long = true;
  }
}

}  // namespace

int run_stdio(Service& service, std::istream& in, std::ostream& out) {
  using nlohmann::json;
  std::string line;
  const size_t max_line = service.limits().max_body_bytes + 4096;
  bool too_long = false;
  while (read_line(in, line, max_line, too_long)) {
    json reply;
    if (too_long) {
      const std::string msg = "request line longer than " + std::to_string(max_line) +
                              " bytes (the body limit, --max-body, and 4096 for the envelope)";
      reply = {{"status", 413}, {"body", {{"error", msg}, {"status", 413}}}};
      out << reply.dump() << "\n" << std::flush;
      if (service.exchange_log()) service.exchange_log()->stdio("", reply);
      continue;
    }
    if (line.find_first_not_of(" \t\r") == std::string::npos) continue;
    try {
      const json req = parse_json_unique(line);
      if (!req.is_object()) throw std::runtime_error("request: expected a JSON object");
      for (auto it = req.begin(); it != req.end(); ++it)
        if (it.key() != "method" && it.key() != "path" && it.key() != "body")
          throw std::runtime_error("unknown field '" + echo(it.key()) + "' (allowed: body, method, path)");
      if (!req.contains("method") || !req["method"].is_string()) throw std::runtime_error("field 'method': expected a string");
      if (!req.contains("path") || !req["path"].is_string()) throw std::runtime_error("field 'path': expected a string");
      const std::string body = req.contains("body") ? req["body"].dump() : "";
      Reply r =
          service.handle(Request{req["method"].get<std::string>(), req["path"].get<std::string>(), body, true, ""});
      reply["status"] = r.status;
      reply["body"] = r.content_type == "application/json" ? json::parse(r.body) : json(r.body);
    } catch (const std::exception& e) {
      reply = {{"status", 400}, {"body", {{"error", std::string("malformed request line: ") + e.what()}, {"status", 400}}}};
    }
    out << reply.dump(-1, ' ', false, json::error_handler_t::replace) << "\n" << std::flush;
    if (service.exchange_log()) service.exchange_log()->stdio(line, reply);
  }
  return 0;
}

}  // namespace clips::serve
