#pragma once
// Minimal JSON-over-HTTP POST client shared by the OpenAI-compatible backends:
// libcurl underneath, bounded retries with exponential backoff, and error
// messages that always name the URL. Thread-safe: every call uses its own
// easy handle (taken from a small pool so keep-alive connections are reused).
#include <chrono>
#include <cstddef>
#include <map>
#include <mutex>
#include <nlohmann/json_fwd.hpp>
#include <string>
#include <vector>

#include "lm/language_model.hpp"

namespace clips::lm {

struct HttpOptions {
  std::chrono::milliseconds connect_timeout{10'000};
  std::chrono::milliseconds total_timeout{120'000};  // whole request, per attempt
  // Extra attempts after the first one, for 429, 5xx, connection errors and
  // timeouts. A 5xx that names a missing feature ("not supported", "not
  // implemented", 501) is final and returned at once, as a 4xx is.
  int max_retries = 4;
  std::chrono::milliseconds backoff_initial{500};
  double backoff_factor = 2.0;
  std::chrono::milliseconds backoff_max{20'000};
  // A server's Retry-After is honoured but never waited on longer than this.
  std::chrono::milliseconds retry_after_max{60'000};
  bool retry_on_timeout = true;
  // A server that let one attempt time out is likely hung or overloaded:
  // timeouts get at most this many extra attempts (inside max_retries), so a
  // dead server costs a couple of total_timeouts, not five.
  int max_timeout_retries = 1;
  // Largest reply body accepted, in bytes. A server that streams without end
  // (or a wrong URL serving a huge file) would otherwise fill memory; a scoring
  // reply for a large batch is a few MiB at most. Exceeding it is an error.
  std::size_t max_reply_bytes = kDefaultMaxReplyBytes;
  static constexpr std::size_t kDefaultMaxReplyBytes = std::size_t{16} << 20;  // 16 MiB
};

struct HttpResponse {
  long status = 0;
  std::string body;
  std::map<std::string, std::string> headers;  // lower-case names, last value wins
  int attempts = 1;                             // how many tries it took
};

// Calls curl_global_init exactly once per process (safe from any thread).
void ensure_curl_initialised();

class HttpClient {
 public:
  explicit HttpClient(HttpOptions options = {});
  ~HttpClient();
  HttpClient(const HttpClient&) = delete;
  HttpClient& operator=(const HttpClient&) = delete;

  // POSTs `body` as application/json. Retries transient failures; returns the
  // first non-retryable response (2xx, other 4xx, a 5xx refusal), or throws LmError when the
  // transport fails or the retry budget is used up.
  HttpResponse post_json(const std::string& url, const std::string& body,
                         const std::vector<std::string>& extra_headers) const;

  const HttpOptions& options() const { return options_; }

 private:
  void* acquire_handle() const;
  void release_handle(void* handle) const;

  HttpOptions options_;
  mutable std::mutex pool_mutex_;
  mutable std::vector<void*> pool_;  // idle CURL* handles
};

// The server's own error text from a JSON error body ({"error":{"message":..}},
// {"message":..} or {"detail":..}), or a short prefix of the raw body.
std::string server_error_text(const std::string& body);

// A completions or chat reply body, parsed and checked to be a JSON object
// whose "choices" is an array (the shape both endpoints share); otherwise an
// LmError whose message starts with `context`.
nlohmann::json parse_choices_reply(const std::string& body, const std::string& context);

// Why `url` cannot be a server's base URL ("" when it can): the scheme must be
// http or https, the host non-empty, and a port, when a colon announces one,
// a number from 1 to 65535 (libcurl reads "http://host:/v1" as port 80).
std::string base_url_problem(const std::string& url);

// Helpers shared by the backends.
std::string env_or(const char* name, const std::string& fallback);
std::string join_url(const std::string& base, const std::string& path);

}  // namespace clips::lm
