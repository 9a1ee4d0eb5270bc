#pragma once
// The request handlers of `clips serve`, independent of any socket: a
// function from (method, path, body) to (status, body). The HTTP and the
// JSON-lines front ends only move bytes; tests and fuzzers call handle()
// directly. docs/api.md documents every request and reply.
//
// Thread-safe: distinct sessions run in parallel, one session's requests are
// serialised by its own mutex.
#include <atomic>
#include <chrono>
#include <functional>
#include <iosfwd>
#include <map>
#include <memory>
#include <mutex>
#include <string>
#include <vector>

#include "data/dataset.hpp"
#include "lm/language_model.hpp"
#include "serve/exchange_log.hpp"
#include "serve/messages.hpp"
#include "serve/play_session.hpp"

namespace clips::serve {

// More particles than a shared server gives one session (its "inference"
// field; the OpenAPI document's bound, serve/api_schema.hpp).
constexpr int kMaxSessionParticles = 10'000;

struct ServiceLimits {
  size_t max_body_bytes = 64 * 1024;
  // Each PDDL or pack text of a session created from text ("domain",
  // "problem", "pack"), in bytes.
  size_t max_pddl_bytes = 32 * 1024;
  size_t max_sessions = 64;
  // Sessions one client (address) may hold at once; 0: no limit of its own.
  // Requests that name no client (tests) or carry the owner token are not counted.
  size_t max_client_sessions = 16;
  double idle_seconds = 30 * 60;  // a session untouched this long is deleted
  // When the server is full, a new session replaces the idlest session of
  // the client holding the most, if it has been idle this long (0: never).
  double evict_idle_seconds = 120;
  PlayLimits play;
};

// Fills `out` with `n` bytes from the operating system's cryptographic
// source (getrandom(2); /dev/urandom where it is missing). Throws
// std::system_error when neither answers.
void os_random_bytes(void* out, size_t n);
using RandomSource = std::function<void(void* out, size_t n)>;

// A nlohmann::json error as a short message of our own, without the
// library's "[json.exception.parse_error.101]" tag, quoting at most a few
// bytes of the input.
std::string json_error_text(const std::exception& e);

// Parses a JSON text, rejecting an object that repeats a key (anywhere in
// the text): throws nlohmann::json::exception or std::invalid_argument
// naming the repeated key.
nlohmann::json parse_json_unique(const std::string& text);

// A static file of the web page (embedded in the binary at build time).
struct Asset {
  const char* content_type;
  std::string_view body;
};
const std::map<std::string, Asset>& web_assets();  // "/index.html", "/app.js", ...
// data/schema/serve-api.openapi.json as shipped ("/serve-api.openapi.json").
const std::map<std::string, Asset>& api_documents();

// The language model for the sessions of one domain (its pack, PDDL domain
// and the problems it will hear about); the server's own model when unset.
using DomainLanguageModel = std::function<std::shared_ptr<lm::LanguageModel>(
    const domains::Pack&, const pddl::Domain&, const std::vector<const pddl::Problem*>&)>;
// The same for the sessions of a served dataset (language::make_dataset_language_model,
// as `clips infer` hears them).
using DatasetLanguageModel = std::function<std::shared_ptr<lm::LanguageModel>(const data::Dataset&)>;

class Service {
 public:
  using Clock = std::chrono::steady_clock;

  // Datasets are loaded now, from these folders only; requests name them by
  // their folder's base name. Throws InputError for a bad or repeated folder.
  Service(const std::vector<std::string>& dataset_dirs, ServiceLimits limits, std::shared_ptr<lm::LanguageModel> lm,
          std::function<Clock::time_point()> now = Clock::now);

  // Call before serving: where the sessions of each domain get their
  // language model (e.g. the embedded model trained on a domain's own
  // corpus). Models are built at a domain's first session and kept.
  void set_domain_language_model(DomainLanguageModel f) { domain_lm_ = std::move(f); }
  void set_dataset_language_model(DatasetLanguageModel f) { dataset_lm_ = std::move(f); }
  // Builds each served dataset's model now and trains (or loads from the
  // cache) every prompt block its problems use, one line per dataset on
  // `log`, so that a session's first instruction does not wait for a
  // training. Call after the setters, before serving.
  void prepare_language_models(std::ostream& log);
  // Where session ids come from (16 bytes each, written as 32 hex digits):
  // os_random_bytes unless a test says otherwise. Ids must not be guessable:
  // whoever knows one may read and play that session.
  void set_random_source(RandomSource source) { random_ = std::move(source); }

  Reply handle(const Request& request);  // logged to exchange_log() when there is one
  Reply handle(const std::string& method, const std::string& path, const std::string& body) {
    return handle(Request{method, path, body, false, ""});
  }

  // The methods a path answers to ("GET, HEAD", "POST", ...; HEAD with
  // every GET), or "" when the path names nothing.
  static std::string allowed_methods(const std::string& path);

  // Deletes sessions idle for longer than limits.idle_seconds (not those in
  // use right now); returns how many went.
  size_t expire_idle();
  size_t live_sessions() const;
  const ServiceLimits& limits() const { return limits_; }
  // $CLIPS_SERVE_EXCHANGE_LOG's log (serve/exchange_log.hpp), or null.
  const std::shared_ptr<ExchangeLog>& exchange_log() const { return exchange_log_; }

 private:
  struct Entry {
    std::mutex mutex;  // serialises this session's requests
    std::unique_ptr<PlaySession> session;
    std::atomic<int64_t> last_used{0};  // Clock ticks
    int64_t created = 0;                 // Clock ticks
    std::string dataset, problem;        // as created ("" dataset: PDDL text)
    std::string client;                  // who created it ("" when not counted)
  };
  // A served folder: its dataset and, once a session needed it, its model.
  struct Served {
    std::shared_ptr<const data::Dataset> dataset;
    std::mutex lm_mutex;  // held while its model is built: other folders' sessions do not wait
    std::shared_ptr<lm::LanguageModel> lm;  // guarded by lm_mutex
    // Each problem's candidate goals (labels), for the catalogue: the page
    // offers them as the player's goal.
    std::map<std::string, std::vector<std::string>> problem_goals;
  };
  Reply respond(const Request& request);
  std::shared_ptr<Entry> find(const std::string& id);
  Reply create(const std::string& body, const std::string& client);
  std::shared_ptr<lm::LanguageModel> dataset_lm(Served& served);
  std::shared_ptr<lm::LanguageModel> text_lm(const PlaySetup& setup, const std::string& key);
  Reply datasets() const;
  Reply list_sessions();
  Reply delete_all_sessions();
  Reply on_session(const std::string& method, const std::string& id, const std::string& op, const std::string& body);
  std::string new_id();
  size_t expire_locked(int64_t now);
  // When full: takes out the session a new one may replace (see
  // ServiceLimits::evict_idle_seconds), or null.
  std::shared_ptr<Entry> evict_locked(int64_t now);

  ServiceLimits limits_;
  std::shared_ptr<lm::LanguageModel> lm_;
  std::function<Clock::time_point()> now_;
  std::map<std::string, Served> datasets_;
  DomainLanguageModel domain_lm_;    // sessions on PDDL text
  DatasetLanguageModel dataset_lm_;  // sessions on a served dataset
  std::mutex lm_mutex_;  // guards text_lms_; held while one of them is built
  std::vector<std::pair<std::string, std::shared_ptr<lm::LanguageModel>>> text_lms_;  // newest last
  mutable std::mutex mutex_;  // guards sessions_, pending_, pending_by_client_, random_
  std::map<std::string, std::shared_ptr<Entry>> sessions_;
  size_t pending_ = 0;  // sessions being created (they hold a slot)
  std::map<std::string, size_t> pending_by_client_;
  RandomSource random_ = os_random_bytes;
  std::shared_ptr<ExchangeLog> exchange_log_ = ExchangeLog::from_environment();
};

}  // namespace clips::serve
