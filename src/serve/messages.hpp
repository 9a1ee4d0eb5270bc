#pragma once
// A request to the service and its reply, as every transport of `clips
// serve` (HTTP, JSON lines, tests) hands them over.
#include <string>
#include <utility>
#include <vector>

namespace clips::serve {

struct Reply {
  int status = 200;
  std::string body;
  std::string content_type = "application/json";
  std::vector<std::pair<std::string, std::string>> headers;  // extra headers (e.g. Allow on a 405)
};

// One request as the handlers see it. `owner`: the request proved it comes
// from whoever started the server (HTTP: the owner token; stdio: always),
// which may list and delete every session. `client`: who sent it, for the
// per-client quotas (HTTP: the peer's address; "" when unknown).
struct Request {
  std::string method;
  std::string path;
  std::string body;
  bool owner = false;
  std::string client;
};

// At most `max_bytes` bytes of `text` (cut at a UTF-8 character boundary,
// with a note of the full length), for echoing request values in errors.
inline std::string echo(const std::string& text, size_t max_bytes = 64) {
  if (text.size() <= max_bytes) return text;
  size_t cut = max_bytes;
  while (cut > 0 && (static_cast<unsigned char>(text[cut]) & 0xC0) == 0x80) --cut;  // not inside a character
  return text.substr(0, cut) + "... (" + std::to_string(text.size()) + " bytes)";
}

}  // namespace clips::serve
