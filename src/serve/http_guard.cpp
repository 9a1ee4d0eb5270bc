#include "serve/http_guard.hpp"

#include <algorithm>
#include <cctype>

#include <nlohmann/json.hpp>

namespace clips::serve {

namespace {

std::string lower(std::string_view s) {
  std::string out(s);
  for (char& c : out) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return out;
}

std::string_view trim(std::string_view s) {
  while (!s.empty() && (s.front() == ' ' || s.front() == '\t')) s.remove_prefix(1);
  while (!s.empty() && (s.back() == ' ' || s.back() == '\t')) s.remove_suffix(1);
  return s;
}

// RFC 9110 token characters (method and header names).
bool is_token(std::string_view s) {
  if (s.empty()) return false;
  for (unsigned char c : s)
    if (!(std::isalnum(c) || std::string_view("!#$%&'*+-.^_`|~").find(static_cast<char>(c)) != std::string_view::npos))
      return false;
  return true;
}

bool is_ipv4(std::string_view s) {
  int parts = 0;
  size_t i = 0;
  while (i <= s.size()) {
    size_t j = s.find('.', i);
    if (j == std::string_view::npos) j = s.size();
    const std::string_view p = s.substr(i, j - i);
    if (p.empty() || p.size() > 3 || !std::all_of(p.begin(), p.end(), [](char c) { return c >= '0' && c <= '9'; }))
      return false;
    if (std::stoi(std::string(p)) > 255) return false;
    ++parts;
    i = j + 1;
  }
  return parts == 4;
}

bool is_loopback_name(const std::string& name) {
  if (name == "localhost" || name == "[::1]") return true;
  if (name.size() > 10 && name.compare(name.size() - 10, 10, ".localhost") == 0) return true;
  return is_ipv4(name) && name.compare(0, 4, "127.") == 0;
}

std::string json_error(int status, const std::string& message) {
  return nlohmann::json{{"error", message}, {"status", status}}.dump(-1, ' ', false,
                                                                      nlohmann::json::error_handler_t::replace);
}

Reply error(int status, const std::string& message) { return Reply{status, json_error(status, message), "application/json", {}}; }

const char* reason(int status) {
  switch (status) {
    case 200: return "OK";
    case 201: return "Created";
    case 204: return "No Content";
    case 400: return "Bad Request";
    case 401: return "Unauthorized";
    case 403: return "Forbidden";
    case 404: return "Not Found";
    case 405: return "Method Not Allowed";
    case 408: return "Request Timeout";
    case 409: return "Conflict";
    case 411: return "Length Required";
    case 413: return "Content Too Large";
    case 414: return "URI Too Long";
    case 415: return "Unsupported Media Type";
    case 422: return "Unprocessable Content";
    case 429: return "Too Many Requests";
    case 431: return "Request Header Fields Too Large";
    case 500: return "Internal Server Error";
    case 502: return "Bad Gateway";
    case 503: return "Service Unavailable";
    case 504: return "Gateway Timeout";
    default: return "Unknown";
  }
}

// The origin "scheme://host[:port]" lower-cased, without a trailing slash.
std::string normal_origin(std::string_view o) {
  std::string s = lower(trim(o));
  while (!s.empty() && s.back() == '/') s.pop_back();
  return s;
}

// The host of an origin ("http://a.b:8080" -> "a.b"), lower-cased; "" when malformed.
std::string origin_host(const std::string& origin) {
  const size_t scheme = origin.find("://");
  if (scheme == std::string::npos) return "";
  return host_name(std::string_view(origin).substr(scheme + 3));
}

}  // namespace

const std::string* RequestHead::header(std::string_view name) const {
  for (const auto& [n, v] : headers)
    if (n == name) return &v;
  return nullptr;
}

HeadScan scan_head(std::string_view received, RequestHead& head, size_t& head_bytes) {
  size_t eol = received.find('\n');
  if (eol == std::string_view::npos)
    return received.size() > kMaxRequestLine ? HeadScan::request_line_too_long : HeadScan::incomplete;
  std::string_view line = received.substr(0, eol);
  if (!line.empty() && line.back() == '\r') line.remove_suffix(1);
  if (line.size() > kMaxRequestLine) return HeadScan::request_line_too_long;
  // The head must end within the limit before it is parsed at all.
  size_t pos = eol + 1;
  std::vector<std::string_view> lines;
  for (;;) {
    const size_t next = received.find('\n', pos);
    if (next == std::string_view::npos) {
      if (received.size() - pos > kMaxHeaderLine || received.size() > kMaxHead) return HeadScan::too_large;
      return HeadScan::incomplete;
    }
    std::string_view h = received.substr(pos, next - pos);
    if (!h.empty() && h.back() == '\r') h.remove_suffix(1);
    if (h.size() > kMaxHeaderLine || next + 1 > kMaxHead) return HeadScan::too_large;
    pos = next + 1;
    if (h.empty()) break;
    lines.push_back(h);
  }
  head = RequestHead{};
  const size_t sp1 = line.find(' ');
  const size_t sp2 = sp1 == std::string_view::npos ? sp1 : line.find(' ', sp1 + 1);
  if (sp2 == std::string_view::npos || line.find(' ', sp2 + 1) != std::string_view::npos) return HeadScan::malformed;
  head.method = std::string(line.substr(0, sp1));
  head.target = std::string(line.substr(sp1 + 1, sp2 - sp1 - 1));
  head.version = std::string(line.substr(sp2 + 1));
  if (!is_token(head.method) || head.target.empty() || (head.version != "HTTP/1.1" && head.version != "HTTP/1.0"))
    return HeadScan::malformed;
  for (unsigned char c : head.target)
    if (c <= 0x20 || c >= 0x7f) return HeadScan::malformed;
  for (std::string_view h : lines) {
    const size_t colon = h.find(':');
    if (colon == std::string_view::npos || !is_token(h.substr(0, colon))) return HeadScan::malformed;
    const std::string_view value = trim(h.substr(colon + 1));
    for (unsigned char c : value)
      if ((c < 0x20 && c != '\t') || c == 0x7f) return HeadScan::malformed;
    head.headers.emplace_back(lower(h.substr(0, colon)), std::string(value));
  }
  head_bytes = pos;
  return HeadScan::complete;
}

std::string host_name(std::string_view host_header) {
  std::string_view h = trim(host_header);
  if (!h.empty() && h.front() == '[') {
    const size_t close = h.find(']');
    return close == std::string_view::npos ? "" : lower(h.substr(0, close + 1));
  }
  const size_t colon = h.rfind(':');
  if (colon != std::string_view::npos) h = h.substr(0, colon);
  return lower(h);
}

bool host_allowed(std::string_view host_header, const GuardPolicy& policy) {
  const std::string name = host_name(host_header);
  if (name.empty()) return false;
  if (is_loopback_name(name) || is_ipv4(name) || name.front() == '[') return true;
  if (name == lower(policy.listen_host)) return true;
  for (const auto& o : policy.allow_origins)
    if (origin_host(normal_origin(o)) == name) return true;
  return false;
}

OriginVerdict check_origin(const RequestHead& head, const GuardPolicy& policy) {
  const std::string* origin = head.header("origin");
  if (!origin) return OriginVerdict::none;
  const std::string o = normal_origin(*origin);
  const std::string* host = head.header("host");
  if (host && o == "http://" + lower(trim(*host))) return OriginVerdict::same;
  for (const auto& a : policy.allow_origins)
    if (a == "*" || normal_origin(a) == o) return OriginVerdict::allowed_cross;
  if (o.compare(0, 7, "http://") == 0 && is_loopback_name(origin_host(o))) return OriginVerdict::allowed_cross;
  return OriginVerdict::refused;
}

std::optional<Reply> screen_request(const RequestHead& head, const GuardPolicy& policy) {
  int hosts = 0;
  for (const auto& h : head.headers) hosts += h.first == "host";
  if (hosts > 1) return error(400, "more than one Host header");
  if (const std::string* host = head.header("host"); host && !host_allowed(*host, policy))
    return error(403, "Host '" + echo(*host) +
                          "' is not served (only IP addresses, localhost, --host and the hosts of --allow-origin: "
                          "other names are how a DNS-rebinding page reaches a local server)");
  const OriginVerdict origin = check_origin(head, policy);
  if (origin == OriginVerdict::refused)
    return error(403, "Origin '" + echo(*head.header("origin")) +
                          "' may not use this server (same origin, loopback pages and --allow-origin only)");

  const std::string path = head.target.substr(0, head.target.find('?'));
  if (head.target == "*") {
    if (head.method != "OPTIONS") return error(400, "request target '*' is for OPTIONS only");
    Reply r{204, "", "", {{"Allow", "GET, HEAD, POST, DELETE, OPTIONS"}}};
    return r;
  }
  if (head.target.front() != '/') return error(400, "request target must be a path starting with '/'");
  const std::string allow_api = policy.allowed_methods ? policy.allowed_methods(path) : "";
  if (allow_api.empty()) return error(404, "no route " + echo(head.method, 16) + " " + echo(path));
  const std::string allow = allow_api + ", OPTIONS";
  if (head.method == "OPTIONS") {
    Reply r{204, "", "", {{"Allow", allow}}};
    if (origin == OriginVerdict::allowed_cross) {
      r.headers.emplace_back("Access-Control-Allow-Origin", *head.header("origin"));
      r.headers.emplace_back("Access-Control-Allow-Methods", allow_api);
      r.headers.emplace_back("Access-Control-Allow-Headers", "Content-Type, Authorization");
      r.headers.emplace_back("Access-Control-Max-Age", "600");
      r.headers.emplace_back("Vary", "Origin");
    }
    return r;
  }
  const std::string method = head.method == "HEAD" ? "GET" : head.method;
  bool known = false;
  for (size_t i = 0; i < allow_api.size();) {
    size_t j = allow_api.find(',', i);
    if (j == std::string::npos) j = allow_api.size();
    known |= std::string_view(allow_api).substr(i, j - i) == method;
    i = j + 2;
  }
  if (!known) {
    Reply r = error(405, echo(head.method, 16) + " " + echo(path) + ": allowed methods are " + allow);
    r.headers.emplace_back("Allow", allow);
    return r;
  }

  if (head.header("transfer-encoding"))
    return error(411, "Transfer-Encoding is not accepted: send the body with a Content-Length");
  const std::string* length = nullptr;
  for (const auto& h : head.headers)
    if (h.first == "content-length") {
      if (length && *length != h.second) return error(400, "conflicting Content-Length headers");
      length = &h.second;
    }
  if (!length) {
    if (head.method == "POST") return error(411, "POST needs a Content-Length header (0 for no body)");
    return std::nullopt;
  }
  if (length->empty() || length->size() > 18 ||
      !std::all_of(length->begin(), length->end(), [](char c) { return c >= '0' && c <= '9'; }))
    return error(400, "Content-Length '" + echo(*length) + "' is not a byte count");
  const size_t bytes = std::stoull(*length);
  if (bytes > policy.max_body_bytes)
    return error(413, "request body of " + std::to_string(bytes) + " bytes exceeds the limit of " +
                          std::to_string(policy.max_body_bytes) + " bytes (--max-body)");
  if (bytes > 0 && head.method == "POST") {
    const std::string* type = head.header("content-type");
    const std::string media = type ? lower(trim(std::string_view(*type).substr(0, type->find(';')))) : "";
    if (media != "application/json")
      return error(415, "Content-Type '" + echo(type ? *type : "") + "': request bodies must be application/json");
  }
  return std::nullopt;
}

std::string format_response(const Reply& reply, bool head_only) {
  std::string out = "HTTP/1.1 " + std::to_string(reply.status) + " " + reason(reply.status) + "\r\n";
  for (const auto& [name, value] : reply.headers) out += name + ": " + value + "\r\n";
  if (reply.status != 204 && reply.status != 304) {
    if (!reply.content_type.empty()) out += "Content-Type: " + reply.content_type + "\r\n";
    out += "Content-Length: " + std::to_string(reply.body.size()) + "\r\n";
  }
  out += "Connection: close\r\n\r\n";
  if (!head_only && reply.status != 204) out += reply.body;
  return out;
}

}  // namespace clips::serve
