// The JSON-lines front end of `clips serve --stdio` (serve::run_stdio, the
// very function `clips serve --stdio` runs on stdin/stdout), without a
// process. One input is up to kMaxLines lines; each is fed to run_stdio as
// its whole standard input, so every line is one request
//
//   {"method": "POST", "path": "/api/sessions", "body": {...}}
//
// and "$ID" in a line stands for the id of the latest session this input
// created (as in the serve target), so that one input can create a session
// and then act on it. The stdio caller is the owner: GET and DELETE
// /api/sessions list and delete every session.
//
// Checked for every line: a line holding anything but blanks gets exactly one
// reply line, a blank line none; the reply is a JSON object
// {"status": S, "body": B} with S in 200..599 other than 500 (an internal
// error), and when S >= 400 and B is an object, B is {"error": text,
// "status": S}. Every session an input creates is deleted at its end.
//
// The service is set up as in the serve target (small example datasets,
// embedded language model, tiny search budgets) with a body limit of 512
// bytes, so that a line over the limit (512 + 4096 bytes) is within reach.
#include <chrono>
#include <memory>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

#include <nlohmann/json.hpp>

#include "fuzz/fuzz_target.hpp"
#include "lm/embedded_model.hpp"
#include "serve/frontends.hpp"
#include "serve/service.hpp"
#include "util/data_dir.hpp"

namespace {

using clips::serve::Service;

constexpr size_t kMaxLines = 8;

int64_t& fake_seconds() {
  static int64_t s = 1000;
  return s;
}

Service& service() {
  static Service s = [] {
    clips::serve::ServiceLimits limits;
    limits.max_body_bytes = 512;
    limits.max_sessions = 2;
    limits.idle_seconds = 600;
    limits.play.inference_nodes = 64;
    limits.play.assist_nodes = 64;
    limits.play.search_seconds = 0.02;
    limits.play.max_steps = 24;
    limits.play.max_utterance_bytes = 120;
    return Service({clips::util::data_path("examples/doors-keys-gems"), clips::util::data_path("datasets/workshop")},
                   limits, std::make_shared<clips::lm::EmbeddedLanguageModel>(), [] {
                     return Service::Clock::time_point(std::chrono::duration_cast<Service::Clock::duration>(
                         std::chrono::seconds(fake_seconds())));
                   });
  }();
  return s;
}

void replace_all(std::string& s, const std::string& from, const std::string& to) {
  for (size_t i = s.find(from); i != std::string::npos; i = s.find(from, i + to.size())) s.replace(i, from.size(), to);
}

bool blank(const std::string& line) { return line.find_first_not_of(" \t\r") == std::string::npos; }

// Runs one line through run_stdio; returns the id of a session it created ("" if none).
std::string run_line(Service& s, const std::string& line, bool newline) {
  std::istringstream in(newline ? line + "\n" : line);
  std::ostringstream out;
  if (clips::serve::run_stdio(s, in, out) != 0) __builtin_trap();
  const std::string text = out.str();
  if (blank(line)) {
    if (!text.empty()) __builtin_trap();  // a blank line is skipped, unanswered
    return "";
  }
  // Exactly one reply line.
  if (text.empty() || text.back() != '\n' || text.find('\n') != text.size() - 1) __builtin_trap();
  const auto reply = nlohmann::json::parse(text, nullptr, false);
  if (reply.is_discarded() || !reply.is_object() || reply.size() != 2 || !reply.contains("status") ||
      !reply["status"].is_number_integer() || !reply.contains("body"))
    __builtin_trap();
  const int status = reply["status"].get<int>();
  if (status < 200 || status > 599 || status == 500) __builtin_trap();
  const auto& body = reply["body"];
  if (status >= 400 && body.is_object()) {
    if (!body.contains("error") || !body["error"].is_string() || body.value("status", 0) != status) __builtin_trap();
  }
  if (status == 201) {
    if (!body.is_object() || !body.contains("id") || !body["id"].is_string() || body["id"].get<std::string>().size() != 32)
      __builtin_trap();
    return body["id"].get<std::string>();
  }
  return "";
}

}  // namespace

#ifdef CLIPS_LIBFUZZER
// Load the datasets and train the embedded model's few-shot blocks (the
// workshop's model is trained on its own names at its first session: 20 s
// under ASan) before the first input, so that neither counts against -timeout.
extern "C" int LLVMFuzzerInitialize(int*, char***) {
  Service& s = service();
  const std::pair<const char*, const char*> kStarts[] = {{"doors-keys-gems", "e1"}, {"doors-keys-gems", "e2"}, {"workshop", "1"}};
  for (const auto& [dataset, problem] : kStarts) {
    const nlohmann::json create = {{"method", "POST"}, {"path", "/api/sessions"},
                                   {"body", {{"dataset", dataset}, {"problem", problem}}}};
    const std::string id = run_line(s, create.dump(), true);
    const std::string at = "/api/sessions/" + id;
    run_line(s, R"({"method":"POST","path":")" + at + R"(/hear","body":{"utterance":"Can you get me the yellow key?"}})", true);
    run_line(s, R"({"method":"POST","path":")" + at + R"(/assist","body":{"apply":true}})", true);
    run_line(s, R"({"method":"DELETE","path":")" + at + R"("})", true);
  }
  return 0;
}
#endif

CLIPS_FUZZ_TARGET(stdio) {
  Service& s = service();
  const std::string text = clips::fuzz::as_text(data, size);
  std::vector<std::string> created;
  size_t start = 0;
  for (size_t n = 0; n < kMaxLines && start < text.size(); ++n) {
    const size_t end = text.find('\n', start);
    const bool newline = end != std::string::npos;
    std::string line = text.substr(start, newline ? end - start : std::string::npos);
    start = newline ? end + 1 : text.size();
    // A line "T" moves the service's clock past the idle timeout.
    if (line == "T") {
      fake_seconds() += 3600;
      continue;
    }
    replace_all(line, "$ID", created.empty() ? "" : created.back());
    if (std::string id = run_line(s, line, newline); !id.empty()) created.push_back(id);
  }
  for (const auto& id : created) s.handle("DELETE", "/api/sessions/" + id, "");
  // A live session left by an earlier input (none should be) would fill the service.
  if (s.live_sessions() != 0) __builtin_trap();
  return 0;
}
