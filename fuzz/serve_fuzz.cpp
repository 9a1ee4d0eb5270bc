// The request handlers of `clips serve` (serve::Service::handle, which the
// HTTP and the JSON-lines front ends both call), without a socket. One input
// is a short conversation: up to kMaxRequests requests, separated by a line
// "~~~", each
//
//   <method byte><path>\n<body>
//
// The method byte G, P, D, U picks GET, POST, DELETE, PUT; T advances the
// service's clock past the idle timeout (and sends nothing); any other byte
// picks one of the four methods by its value. In path and body, "$ID" stands
// for the id of the latest session this input created, so one input can
// create a session and then act on it, hear, assist, undo, ...
//
// The service serves the repo's small Doors-Keys-Gems example and the
// workshop dataset (a text scene) with the embedded language model
// and tiny search budgets: the handlers are the target (search has its own
// targets), and an input that opens the most sessions must stay well inside
// the 1 s per-input limit under instrumentation. Every session an input creates is deleted at its
// end, so inputs do not depend on each other.
//
// Checked on every reply: a status in 200..599 other than 500 (an internal
// error is an exception the handlers did not expect); a JSON reply parses,
// an error reply is {"error": text, "status": its status}, a created session
// has a 32-character id.
#include <chrono>
#include <memory>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "fuzz/fuzz_target.hpp"
#include "lm/embedded_model.hpp"
#include "serve/service.hpp"
#include "util/data_dir.hpp"

namespace {

using clips::serve::Reply;
using clips::serve::Service;

constexpr size_t kMaxRequests = 8;
const std::string kSeparator = "\n~~~\n";

struct Clock {
  int64_t seconds = 1000;
  Service::Clock::time_point now() const {
    return Service::Clock::time_point(
        std::chrono::duration_cast<Service::Clock::duration>(std::chrono::seconds(seconds)));
  }
};

Clock& fake_clock() {
  static Clock c;
  return c;
}

Service& service() {
  static Service s = [] {
    clips::serve::ServiceLimits limits;
    limits.max_body_bytes = 2048;
    limits.max_sessions = 2;
    limits.idle_seconds = 600;
    limits.play.inference_nodes = 64;
    limits.play.assist_nodes = 64;
    limits.play.search_seconds = 0.02;
    limits.play.max_steps = 24;
    limits.play.max_utterance_bytes = 120;
    return Service({clips::util::data_path("examples/doors-keys-gems"), clips::util::data_path("datasets/workshop")},
                   limits, std::make_shared<clips::lm::EmbeddedLanguageModel>(),
                   [] { return fake_clock().now(); });
  }();
  return s;
}

std::string method_of(unsigned char c) {
  switch (c) {
    case 'G': return "GET";
    case 'P': return "POST";
    case 'D': return "DELETE";
    case 'U': return "PUT";
  }
  static const char* const kMethods[] = {"GET", "POST", "DELETE", "PUT"};
  return kMethods[c % 4];
}

void replace_all(std::string& s, const std::string& from, const std::string& to) {
  if (from.empty()) return;
  for (size_t i = s.find(from); i != std::string::npos; i = s.find(from, i + to.size())) s.replace(i, from.size(), to);
}

void check(const Reply& r) {
  if (r.status < 200 || r.status > 599 || r.status == 500) __builtin_trap();
  if (r.content_type != "application/json") return;
  const auto j = nlohmann::json::parse(r.body, nullptr, false);
  if (j.is_discarded() || !j.is_object()) __builtin_trap();
  if (r.status >= 400) {
    if (!j.contains("error") || !j["error"].is_string() || j.value("status", 0) != r.status) __builtin_trap();
  } else if (r.status == 201) {
    if (!j.contains("id") || !j["id"].is_string() || j["id"].get<std::string>().size() != 32) __builtin_trap();
  }
}

}  // namespace

#ifdef CLIPS_LIBFUZZER
// Load the datasets and train the language model's few-shot blocks before the
// first input (a session per method that hears an instruction and assists),
// so neither counts against -timeout. Trained models are cached on disk as
// for any other run.
extern "C" int LLVMFuzzerInitialize(int*, char***) {
  Service& s = service();
  for (const auto& method : clips::serve::play_methods()) {
    for (const char* problem : {"e1", "e2"}) {
      const Reply r = s.handle("POST", "/api/sessions",
                               nlohmann::json{{"dataset", "doors-keys-gems"}, {"problem", problem}, {"method", method}}.dump());
      const std::string id = nlohmann::json::parse(r.body).value("id", "");
      const std::string at = "/api/sessions/" + id;
      s.handle("POST", at + "/hear", R"({"utterance":"Can you get me the yellow key?"})");
      s.handle("POST", at + "/act", R"j({"action":"(wait human)"})j");
      s.handle("POST", at + "/assist", R"({"apply":true})");
      s.handle("GET", at, "");
      s.handle("DELETE", at, "");
    }
  }
  return 0;
}
#endif

CLIPS_FUZZ_TARGET(serve) {
  Service& s = service();
  const std::string text = clips::fuzz::as_text(data, size);
  std::vector<std::string> created;
  size_t start = 0;
  for (size_t n = 0; n < kMaxRequests && start < text.size(); ++n) {
    size_t end = text.find(kSeparator, start);
    if (end == std::string::npos) end = text.size();
    const std::string request = text.substr(start, end - start);
    start = end == text.size() ? end : end + kSeparator.size();
    if (request.empty()) continue;
    if (request[0] == 'T') {
      fake_clock().seconds += 3600;
      continue;
    }
    const std::string method = method_of(static_cast<unsigned char>(request[0]));
    const size_t newline = request.find('\n');
    std::string path = request.substr(1, newline == std::string::npos ? std::string::npos : newline - 1);
    std::string body = newline == std::string::npos ? "" : request.substr(newline + 1);
    const std::string id = created.empty() ? "" : created.back();
    replace_all(path, "$ID", id);
    replace_all(body, "$ID", id);
    const Reply r = s.handle(method, path, body);
    check(r);
    if (r.status == 201) created.push_back(nlohmann::json::parse(r.body)["id"].get<std::string>());
  }
  for (const auto& id : created) s.handle("DELETE", "/api/sessions/" + id, "");
  // A live session left by an earlier input (none should be) would fill the server.
  if (s.live_sessions() != 0) __builtin_trap();
  return 0;
}
