#pragma once
// Every API exchange of `clips serve` as one JSON line, appended to the file
// $CLIPS_SERVE_EXCHANGE_LOG names: {"method", "path", "request" (the body as
// JSON, or as text when it is not JSON; null when empty), "status", "reply"
// (JSON; text for the page)}, and on --stdio also {"stdio_request" (the line,
// parsed when it parses), "stdio_reply"}. For whoever wires a robot or a ROS
// node to the server (what exactly went over the wire), and for the test
// that checks every request and reply the server tests send against
// data/schema/serve-api.openapi.json. Off when the variable is unset or empty.
#include <memory>
#include <mutex>
#include <nlohmann/json.hpp>
#include <string>

namespace clips::serve {

class ExchangeLog {
 public:
  // The log $CLIPS_SERVE_EXCHANGE_LOG names, or null when it is unset or empty.
  static std::shared_ptr<ExchangeLog> from_environment();
  explicit ExchangeLog(std::string path) : path_(std::move(path)) {}

  // One exchange through the handlers; `content_type` says whether `reply` is JSON.
  void exchange(const std::string& method, const std::string& path, const std::string& request, int status,
                const std::string& content_type, const std::string& reply);
  // One line of --stdio and the line answered.
  void stdio(const std::string& request_line, const nlohmann::json& reply);

 private:
  // Appends with one write() on an O_APPEND descriptor, so that lines from
  // several threads or processes sharing the file do not interleave.
  void append(const nlohmann::json& line);
  std::string path_;
};

}  // namespace clips::serve
