#include "serve/exchange_log.hpp"

#include <fcntl.h>
#include <unistd.h>

#include <cstdlib>

namespace clips::serve {

using nlohmann::json;

namespace {

// The text as JSON when it is JSON, else as a string; null when empty.
json as_json(const std::string& text) {
  if (text.empty()) return nullptr;
  json j = json::parse(text, nullptr, /*allow_exceptions=*/false);
  return j.is_discarded() ? json(text) : j;
}

}  // namespace

std::shared_ptr<ExchangeLog> ExchangeLog::from_environment() {
  const char* path = std::getenv("CLIPS_SERVE_EXCHANGE_LOG");
  if (path == nullptr || *path == '\0') return nullptr;
  return std::make_shared<ExchangeLog>(path);
}

void ExchangeLog::exchange(const std::string& method, const std::string& path, const std::string& request,
                           int status, const std::string& content_type, const std::string& reply) {
  append({{"method", method},
          {"path", path},
          {"request", as_json(request)},
          {"status", status},
          {"content_type", content_type},
          {"reply", content_type == "application/json" ? as_json(reply) : json(reply.substr(0, 200))}});
}

void ExchangeLog::stdio(const std::string& request_line, const json& reply) {
  append({{"stdio_request", as_json(request_line)}, {"stdio_reply", reply}});
}

void ExchangeLog::append(const json& line) {
  const std::string text = line.dump(-1, ' ', false, json::error_handler_t::replace) + "\n";
  const int fd = ::open(path_.c_str(), O_WRONLY | O_CREAT | O_APPEND | O_CLOEXEC, 0644);
  if (fd < 0) return;  // a log that cannot be written must not fail a request
  const ssize_t written = ::write(fd, text.data(), text.size());
  (void)written;
  ::close(fd);
}

}  // namespace clips::serve
