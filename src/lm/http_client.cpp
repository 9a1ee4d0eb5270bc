#include "lm/http_client.hpp"

#include <curl/curl.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <ctime>
#include <nlohmann/json.hpp>
#include <optional>
#include <thread>

#include "util/shared_library.hpp"

namespace clips::lm {

namespace {

// libcurl, opened on first use: a call of the CLI that talks to no server
// does not load it (with its TLS, SSH, LDAP and Kerberos libraries, most of
// a short call's start-up time).
struct Curl {
  template <class F>
  F get(const char* name) const { return lib.function<F>(name); }
  util::SharedLibrary lib{{"libcurl.so.4"}, "the LM client needs libcurl (Debian: apt-get install libcurl4)"};
  decltype(&::curl_global_init) global_init = get<decltype(&::curl_global_init)>("curl_global_init");
  decltype(&::curl_getdate) getdate = get<decltype(&::curl_getdate)>("curl_getdate");
  decltype(&::curl_easy_init) easy_init = get<decltype(&::curl_easy_init)>("curl_easy_init");
  decltype(&::curl_easy_reset) easy_reset = get<decltype(&::curl_easy_reset)>("curl_easy_reset");
  decltype(&::curl_easy_cleanup) easy_cleanup = get<decltype(&::curl_easy_cleanup)>("curl_easy_cleanup");
  decltype(&::curl_easy_setopt) easy_setopt = get<decltype(&::curl_easy_setopt)>("curl_easy_setopt");
  decltype(&::curl_easy_perform) easy_perform = get<decltype(&::curl_easy_perform)>("curl_easy_perform");
  decltype(&::curl_easy_getinfo) easy_getinfo = get<decltype(&::curl_easy_getinfo)>("curl_easy_getinfo");
  decltype(&::curl_easy_strerror) easy_strerror = get<decltype(&::curl_easy_strerror)>("curl_easy_strerror");
  decltype(&::curl_slist_append) slist_append = get<decltype(&::curl_slist_append)>("curl_slist_append");
  decltype(&::curl_slist_free_all) slist_free_all = get<decltype(&::curl_slist_free_all)>("curl_slist_free_all");
};

const Curl& curl() {
  try {
    static const Curl c;  // a failed load leaves it unset: the next call tries again
    return c;
  } catch (const util::SharedLibraryError& e) {
    throw LmError(std::string("libcurl: ") + e.what());
  }
}

}  // namespace

void ensure_curl_initialised() {
  static std::once_flag once;
  std::call_once(once, [] {
    if (curl().global_init(CURL_GLOBAL_DEFAULT) != CURLE_OK) {
      throw LmError("libcurl: curl_global_init failed");
    }
  });
}

namespace {

constexpr std::size_t kMaxPooledHandles = 8;

struct Transfer {
  std::string body;
  std::map<std::string, std::string> headers;
  std::size_t max_body = 0;
  bool too_large = false;
};

std::size_t on_body(char* data, std::size_t size, std::size_t count, void* user) {
  auto* t = static_cast<Transfer*>(user);
  const std::size_t n = size * count;
  if (n > t->max_body - t->body.size()) {
    t->too_large = true;
    return 0;  // a short count makes libcurl abort the transfer (CURLE_WRITE_ERROR)
  }
  t->body.append(data, n);
  return n;
}

std::size_t on_header(char* data, std::size_t size, std::size_t count, void* user) {
  auto* t = static_cast<Transfer*>(user);
  std::string line(data, size * count);
  // A new status line (e.g. after "100 Continue") starts a fresh header set.
  if (line.rfind("HTTP/", 0) == 0) {
    t->headers.clear();
  } else if (auto colon = line.find(':'); colon != std::string::npos) {
    std::string name = line.substr(0, colon);
    std::transform(name.begin(), name.end(), name.begin(),
                   [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
    std::string value = line.substr(colon + 1);
    auto not_space = [](unsigned char c) { return !std::isspace(c); };
    value.erase(value.begin(), std::find_if(value.begin(), value.end(), not_space));
    value.erase(std::find_if(value.rbegin(), value.rend(), not_space).base(), value.end());
    t->headers[name] = value;
  }
  return size * count;
}

// A 5xx that names a missing feature is the server's final word: asking
// again gets the same answer (llama.cpp: 500 "Only no echo is supported").
bool is_permanent_refusal(long status, const std::string& body) {
  if (status == 501 || status == 505) return true;
  if (status < 500 || status > 599) return false;
  std::string why = server_error_text(body);
  std::transform(why.begin(), why.end(), why.begin(), [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  for (const char* phrase : {"not supported", "unsupported", "not implemented", "only no echo"})
    if (why.find(phrase) != std::string::npos) return true;
  return false;
}

bool is_retryable_status(long status, const std::string& body) {
  return (status == 408 || status == 429 || (status >= 500 && status <= 599)) && !is_permanent_refusal(status, body);
}

bool is_timeout(CURLcode code) { return code == CURLE_OPERATION_TIMEDOUT; }

// Failures where trying again can plausibly help (the server was busy,
// restarting, or the connection dropped mid-reply).
bool is_transient(CURLcode code) {
  switch (code) {
    case CURLE_COULDNT_CONNECT:
    case CURLE_COULDNT_RESOLVE_HOST:
    case CURLE_SEND_ERROR:
    case CURLE_RECV_ERROR:
    case CURLE_GOT_NOTHING:
    case CURLE_PARTIAL_FILE:
      return true;
    default:
      return false;
  }
}

// Retry-After as delta-seconds or HTTP date; OpenAI also sends retry-after-ms.
std::optional<std::chrono::milliseconds> retry_after(
    const std::map<std::string, std::string>& headers) {
  if (auto it = headers.find("retry-after-ms"); it != headers.end()) {
    char* end = nullptr;
    double ms = std::strtod(it->second.c_str(), &end);
    if (end != it->second.c_str() && std::isfinite(ms) && ms >= 0) {
      return std::chrono::milliseconds(static_cast<long long>(std::min(ms, 1e12)));  // no overflow
    }
  }
  auto it = headers.find("retry-after");
  if (it == headers.end()) return std::nullopt;
  char* end = nullptr;
  double seconds = std::strtod(it->second.c_str(), &end);
  if (end != it->second.c_str() && *end == '\0' && std::isfinite(seconds) && seconds >= 0) {
    return std::chrono::milliseconds(static_cast<long long>(std::min(seconds, 1e9) * 1000.0));
  }
  std::time_t when = curl().getdate(it->second.c_str(), nullptr);
  if (when < 0) return std::nullopt;
  auto wait = std::chrono::system_clock::from_time_t(when) - std::chrono::system_clock::now();
  return std::max(std::chrono::milliseconds(0),
                  std::chrono::duration_cast<std::chrono::milliseconds>(wait));
}

std::string url_host(const std::string& url) {
  auto start = url.find("://");
  start = (start == std::string::npos) ? 0 : start + 3;
  auto end = url.find_first_of("/?#", start);
  std::string authority = url.substr(start, end == std::string::npos ? std::string::npos : end - start);
  if (auto at = authority.rfind('@'); at != std::string::npos) authority = authority.substr(at + 1);
  if (!authority.empty() && authority.front() == '[') {
    return authority.substr(1, authority.find(']') - 1);
  }
  return authority.substr(0, authority.find(':'));
}

bool is_loopback(const std::string& host) {
  return host == "localhost" || host == "::1" || host.rfind("127.", 0) == 0;
}

std::string seconds_text(std::chrono::milliseconds ms) {
  char buf[48];
  std::snprintf(buf, sizeof buf, "%g s", static_cast<double>(ms.count()) / 1000.0);
  return buf;
}

std::string attempts_text(int n) {
  return std::to_string(n) + (n == 1 ? " attempt" : " attempts");
}

}  // namespace

HttpClient::HttpClient(HttpOptions options) : options_(options) {
  ensure_curl_initialised();
  options_.max_retries = std::max(0, options_.max_retries);
}

HttpClient::~HttpClient() {
  for (void* h : pool_) curl().easy_cleanup(static_cast<CURL*>(h));
}

void* HttpClient::acquire_handle() const {
  {
    std::lock_guard lock(pool_mutex_);
    if (!pool_.empty()) {
      void* h = pool_.back();
      pool_.pop_back();
      curl().easy_reset(static_cast<CURL*>(h));  // keeps its connection cache
      return h;
    }
  }
  CURL* h = curl().easy_init();
  if (h == nullptr) throw LmError("libcurl: curl_easy_init failed");
  return h;
}

void HttpClient::release_handle(void* handle) const {
  std::lock_guard lock(pool_mutex_);
  if (pool_.size() < kMaxPooledHandles) {
    pool_.push_back(handle);
  } else {
    curl().easy_cleanup(static_cast<CURL*>(handle));
  }
}

HttpResponse HttpClient::post_json(const std::string& url, const std::string& body,
                                   const std::vector<std::string>& extra_headers) const {
  // Owns the handle for this call and hands it back to the pool on any exit.
  struct Lease {
    const HttpClient* owner;
    CURL* h;
    ~Lease() { owner->release_handle(h); }
  } lease{this, static_cast<CURL*>(acquire_handle())};

  curl_slist* header_list = nullptr;
  header_list = curl().slist_append(header_list, "Content-Type: application/json");
  header_list = curl().slist_append(header_list, "Accept: application/json");
  header_list = curl().slist_append(header_list, "Expect:");  // no 100-continue round trip
  for (const auto& h : extra_headers) header_list = curl().slist_append(header_list, h.c_str());
  struct ListGuard {
    curl_slist* l;
    ~ListGuard() { curl().slist_free_all(l); }
  } list_guard{header_list};

  const bool loopback = is_loopback(url_host(url));
  const int max_attempts = options_.max_retries + 1;
  auto backoff = options_.backoff_initial;

  int timeouts = 0;
  // The waits a server asks for (Retry-After) add up to at most one request
  // timeout: a server asking for a day must not hold the caller for a day.
  std::chrono::milliseconds waited{0};
  for (int attempt = 1;; ++attempt) {
    Transfer t;
    t.max_body = options_.max_reply_bytes;
    char errbuf[CURL_ERROR_SIZE] = {0};
    CURL* h = lease.h;
    curl().easy_setopt(h, CURLOPT_URL, url.c_str());
    // HTTP(S) only: a file:// (or any other) base URL is refused by libcurl.
    curl().easy_setopt(h, CURLOPT_PROTOCOLS_STR, "http,https");
    curl().easy_setopt(h, CURLOPT_REDIR_PROTOCOLS_STR, "http,https");
    curl().easy_setopt(h, CURLOPT_POST, 1L);
    curl().easy_setopt(h, CURLOPT_POSTFIELDS, body.data());
    curl().easy_setopt(h, CURLOPT_POSTFIELDSIZE_LARGE, static_cast<curl_off_t>(body.size()));
    curl().easy_setopt(h, CURLOPT_HTTPHEADER, header_list);
    curl().easy_setopt(h, CURLOPT_WRITEFUNCTION, on_body);
    curl().easy_setopt(h, CURLOPT_WRITEDATA, &t);
    curl().easy_setopt(h, CURLOPT_HEADERFUNCTION, on_header);
    curl().easy_setopt(h, CURLOPT_HEADERDATA, &t);
    curl().easy_setopt(h, CURLOPT_ERRORBUFFER, errbuf);
    curl().easy_setopt(h, CURLOPT_NOSIGNAL, 1L);  // timeouts without SIGALRM: threads are safe
    curl().easy_setopt(h, CURLOPT_CONNECTTIMEOUT_MS,
                     static_cast<long>(options_.connect_timeout.count()));
    curl().easy_setopt(h, CURLOPT_TIMEOUT_MS, static_cast<long>(options_.total_timeout.count()));
    curl().easy_setopt(h, CURLOPT_ACCEPT_ENCODING, "");  // whatever libcurl can decode
    // Local inference servers are never reached through a proxy.
    if (loopback) curl().easy_setopt(h, CURLOPT_NOPROXY, "*");

    CURLcode code = curl().easy_perform(h);
    long status = 0;
    if (code == CURLE_OK) curl().easy_getinfo(h, CURLINFO_RESPONSE_CODE, &status);

    std::optional<std::chrono::milliseconds> server_wait;
    if (t.too_large) {
      // Not transient: the same request would stream the same endless reply.
      throw LmError("POST " + url + ": reply exceeds the cap of " + std::to_string(options_.max_reply_bytes) +
                    " bytes (--lm-max-reply-mb); stopped reading");
    }
    if (code != CURLE_OK) {
      if (is_timeout(code)) ++timeouts;
      const bool retry = is_transient(code) || (is_timeout(code) && options_.retry_on_timeout &&
                                                timeouts <= options_.max_timeout_retries);
      if (!retry || attempt >= max_attempts) {
        std::string detail = errbuf[0] != '\0' ? std::string(errbuf) : curl().easy_strerror(code);
        if (is_timeout(code)) {
          throw LmError("POST " + url + " timed out after " + attempts_text(attempt) +
                        " (connect timeout " + std::to_string(options_.connect_timeout.count()) +
                        " ms, total timeout " + std::to_string(options_.total_timeout.count()) +
                        " ms): " + detail);
        }
        throw LmError("POST " + url + " failed after " + attempts_text(attempt) + ": " + detail +
                      " (curl error " + std::to_string(static_cast<int>(code)) + ")");
      }
    } else if (is_retryable_status(status, t.body)) {
      if (attempt >= max_attempts) {
        throw LmError("POST " + url + ": HTTP " + std::to_string(status) + " after " +
                      attempts_text(attempt) + ", retry budget exhausted: " +
                      server_error_text(t.body));
      }
      server_wait = retry_after(t.headers);
    } else {
      return HttpResponse{status, std::move(t.body), std::move(t.headers), attempt};
    }

    auto wait = std::min(backoff, options_.backoff_max);
    if (server_wait) {
      const auto left = options_.total_timeout - waited;
      if (left.count() <= 0)
        throw LmError("POST " + url + ": HTTP " + std::to_string(status) + " after " + attempts_text(attempt) +
                      ": the server asks to wait " + seconds_text(*server_wait) +
                      " before trying again (Retry-After), and the waits between attempts may add up to the "
                      "request timeout of " + seconds_text(options_.total_timeout) + " (--lm-timeout) at most: " +
                      server_error_text(t.body));
      wait = std::min({*server_wait, options_.retry_after_max, left});
      waited += wait;
    }
    std::this_thread::sleep_for(wait);
    backoff = std::chrono::milliseconds(
        static_cast<long long>(static_cast<double>(backoff.count()) * options_.backoff_factor));
  }
}

nlohmann::json parse_choices_reply(const std::string& body, const std::string& context) {
  nlohmann::json j = nlohmann::json::parse(body, nullptr, /*allow_exceptions=*/false);
  if (j.is_discarded()) {
    // A number beyond a double's range (a log-probability of -1e999) is
    // valid JSON text that no double holds: say so rather than "not JSON".
    try {
      [[maybe_unused]] const nlohmann::json again = nlohmann::json::parse(body);  // throws: which error?
    } catch (const nlohmann::json::out_of_range& e) {
      std::string what = e.what();
      if (const auto at = what.find("] "); at != std::string::npos) what = what.substr(at + 2);
      throw LmError(context + "a number in the body is out of range for a double (" + what.substr(0, 120) +
                    "); log-probabilities must be finite numbers");
    } catch (const nlohmann::json::exception&) {
    }
    throw LmError(context + "body is not valid JSON (" + std::to_string(body.size()) +
                  " bytes: " + server_error_text(body) + ")");
  }
  if (!j.is_object()) throw LmError(context + "body is not a JSON object");
  auto choices = j.find("choices");
  if (choices == j.end() || choices->is_null()) throw LmError(context + "choices missing");
  if (!choices->is_array()) throw LmError(context + "choices is not an array");
  return j;
}

std::string server_error_text(const std::string& body) {
  auto j = nlohmann::json::parse(body, nullptr, /*allow_exceptions=*/false);
  if (j.is_object()) {
    if (auto e = j.find("error"); e != j.end()) {
      if (e->is_string()) return e->get<std::string>();
      if (e->is_object() && e->contains("message") && (*e)["message"].is_string()) {
        return (*e)["message"].get<std::string>();
      }
    }
    for (const char* key : {"message", "detail"}) {
      if (auto m = j.find(key); m != j.end()) return m->is_string() ? m->get<std::string>() : m->dump();
    }
  }
  constexpr std::size_t kMax = 300;
  if (body.empty()) return "(empty body)";
  return body.size() <= kMax ? body : body.substr(0, kMax) + "...";
}

std::string base_url_problem(const std::string& url) {
  size_t start = 0;
  if (url.rfind("http://", 0) == 0) start = 7;
  else if (url.rfind("https://", 0) == 0) start = 8;
  else return "'" + url + "' is not an http:// or https:// URL";
  const size_t end = url.find_first_of("/?#", start);
  std::string authority = url.substr(start, end == std::string::npos ? std::string::npos : end - start);
  if (auto at = authority.rfind('@'); at != std::string::npos) authority = authority.substr(at + 1);
  std::string port;
  bool has_port = false;
  if (!authority.empty() && authority.front() == '[') {
    const size_t close = authority.find(']');
    if (close == std::string::npos || close == 1) return "'" + url + "': malformed [IPv6] host";
    const std::string rest = authority.substr(close + 1);
    if (!rest.empty() && rest.front() != ':') return "'" + url + "': text after the ] of the [IPv6] host";
    has_port = !rest.empty();
    if (has_port) port = rest.substr(1);
  } else {
    const size_t colon = authority.find(':');
    if (colon == 0 || authority.empty()) return "'" + url + "' has no host";
    has_port = colon != std::string::npos;
    if (has_port) port = authority.substr(colon + 1);
  }
  if (has_port) {
    const bool digits = !port.empty() && port.size() <= 5 &&
                        std::all_of(port.begin(), port.end(), [](char c) { return c >= '0' && c <= '9'; });
    if (!digits || std::stoi(port) < 1 || std::stoi(port) > 65535)
      return "'" + url + "': the port after ':' must be a number from 1 to 65535" +
             (port.empty() ? " (it is empty; leave the ':' out for the scheme's own port)" : ", got '" + port + "'");
  }
  return "";
}

std::string env_or(const char* name, const std::string& fallback) {
  const char* v = std::getenv(name);
  return (v != nullptr && *v != '\0') ? std::string(v) : fallback;
}

std::string join_url(const std::string& base, const std::string& path) {
  std::string b = base;
  while (!b.empty() && b.back() == '/') b.pop_back();
  return b + path;
}

}  // namespace clips::lm
