// The request-head checks of `clips serve` (serve/http_guard.hpp), without a
// socket: head parsing and its limits, Host and Origin rules, method and body
// declarations; plus the duplicate-key JSON reader and the echo cut.
#include "serve/http_guard.hpp"
#include "serve/service.hpp"

#include <gtest/gtest.h>

namespace {

using namespace clips::serve;

RequestHead parse(const std::string& text) {
  RequestHead head;
  size_t n = 0;
  EXPECT_EQ(scan_head(text, head, n), HeadScan::complete) << text;
  return head;
}

// The service's routes, as `clips serve` gives them to the guard.
GuardPolicy with_routes(GuardPolicy policy) {
  policy.allowed_methods = &Service::allowed_methods;
  return policy;
}

int screened(const std::string& text, const GuardPolicy& policy = {}) {
  auto r = screen_request(parse(text), with_routes(policy));
  return r ? r->status : 0;
}

TEST(HttpGuard, ScansHeadsAndTheirLimits) {
  RequestHead head;
  size_t n = 0;
  EXPECT_EQ(scan_head("GET / HTTP/1.1\r\nHost: a", head, n), HeadScan::incomplete);
  EXPECT_EQ(scan_head("GET / HTTP/1.1\r\nHost: a\r\n\r\nbody", head, n), HeadScan::complete);
  EXPECT_EQ(n, 27u);
  EXPECT_EQ(head.method, "GET");
  ASSERT_NE(head.header("host"), nullptr);
  EXPECT_EQ(*head.header("host"), "a");
  EXPECT_EQ(scan_head(std::string(kMaxRequestLine + 1, 'G'), head, n), HeadScan::request_line_too_long);
  EXPECT_EQ(scan_head("GET / HTTP/1.1\r\nX: " + std::string(kMaxHeaderLine, 'x'), head, n), HeadScan::too_large);
  std::string many = "GET / HTTP/1.1\r\n";
  while (many.size() <= kMaxHead) many += "X-A: 0123456789012345678901234567890123456789\r\n";
  EXPECT_EQ(scan_head(many, head, n), HeadScan::too_large);
  EXPECT_EQ(scan_head("GET /\r\n\r\n", head, n), HeadScan::malformed);
  EXPECT_EQ(scan_head("GET / HTTP/2.0\r\n\r\n", head, n), HeadScan::malformed);
  EXPECT_EQ(scan_head("GET / HTTP/1.1\r\nno colon\r\n\r\n", head, n), HeadScan::malformed);
  EXPECT_EQ(scan_head("GET / HTTP/1.1\r\nX: a\x01\r\n\r\n", head, n), HeadScan::malformed);
}

TEST(HttpGuard, HostNamesThatARebindingPageWouldSendAreRefused) {
  GuardPolicy p;
  p.listen_host = "127.0.0.1";
  EXPECT_TRUE(host_allowed("127.0.0.1:8080", p));
  EXPECT_TRUE(host_allowed("localhost:8080", p));
  EXPECT_TRUE(host_allowed("LOCALHOST", p));
  EXPECT_TRUE(host_allowed("[::1]:8080", p));
  EXPECT_TRUE(host_allowed("192.168.1.20:8080", p));
  EXPECT_TRUE(host_allowed("play.localhost:8080", p));
  EXPECT_FALSE(host_allowed("attacker.example:8080", p));
  EXPECT_FALSE(host_allowed("127.0.0.1.attacker.example", p));
  EXPECT_FALSE(host_allowed("", p));
  p.listen_host = "robot.lab";
  EXPECT_TRUE(host_allowed("robot.lab:8080", p));
  p.allow_origins = {"https://app.example.org"};
  EXPECT_TRUE(host_allowed("app.example.org", p));
}

TEST(HttpGuard, OriginsAndMethodsAndBodies) {
  GuardPolicy p;
  p.max_body_bytes = 100;
  const std::string h = "Host: 127.0.0.1:9\r\n";
  EXPECT_EQ(screened("GET /api/health HTTP/1.1\r\n" + h + "\r\n", p), 0);
  EXPECT_EQ(screened("GET /api/health HTTP/1.1\r\n" + h + "Origin: http://127.0.0.1:9\r\n\r\n", p), 0);
  EXPECT_EQ(screened("GET /api/health HTTP/1.1\r\n" + h + "Origin: http://localhost:5173\r\n\r\n", p), 0);
  EXPECT_EQ(screened("GET /api/health HTTP/1.1\r\n" + h + "Origin: https://evil.example\r\n\r\n", p), 403);
  EXPECT_EQ(screened("GET /api/health HTTP/1.1\r\n" + h + "Origin: null\r\n\r\n", p), 403);
  EXPECT_EQ(screened("GET /api/health HTTP/1.1\r\nHost: a\r\nHost: 127.0.0.1\r\n\r\n", p), 400);
  EXPECT_EQ(screened("GET /nowhere HTTP/1.1\r\n" + h + "\r\n", p), 404);
  EXPECT_EQ(screened("PUT /api/health HTTP/1.1\r\n" + h + "\r\n", p), 405);
  EXPECT_EQ(screened("POST /api/health HTTP/1.1\r\n" + h + "Content-Length: 0\r\n\r\n", p), 405);
  EXPECT_EQ(screened("OPTIONS /api/health HTTP/1.1\r\n" + h + "\r\n", p), 204);
  EXPECT_EQ(screened("POST /api/sessions HTTP/1.1\r\n" + h + "\r\n", p), 411);
  EXPECT_EQ(screened("POST /api/sessions HTTP/1.1\r\n" + h + "Content-Length: 0\r\n\r\n", p), 0);
  EXPECT_EQ(screened("POST /api/sessions HTTP/1.1\r\n" + h + "Content-Length: 2\r\n\r\n", p), 415);
  EXPECT_EQ(screened("POST /api/sessions HTTP/1.1\r\n" + h + "Content-Length: 2\r\nContent-Type: text/plain\r\n\r\n", p),
            415);
  EXPECT_EQ(screened("POST /api/sessions HTTP/1.1\r\n" + h + "Content-Length: 2\r\nContent-Type: Application/JSON; charset=utf-8\r\n\r\n", p),
            0);
  EXPECT_EQ(screened("POST /api/sessions HTTP/1.1\r\n" + h + "Content-Length: 101\r\nContent-Type: application/json\r\n\r\n", p),
            413);
  EXPECT_EQ(screened("POST /api/sessions HTTP/1.1\r\n" + h + "Content-Length: 1e3\r\n\r\n", p), 400);
  EXPECT_EQ(screened("POST /api/sessions HTTP/1.1\r\n" + h + "Content-Length: 2\r\nContent-Length: 3\r\n\r\n", p), 400);
  EXPECT_EQ(screened("DELETE /api/sessions/x HTTP/1.1\r\n" + h + "Transfer-Encoding: chunked\r\n\r\n", p), 411);
}

TEST(HttpGuard, DuplicateKeysAndEchoCuts) {
  EXPECT_NO_THROW(parse_json_unique(R"({"a":1,"b":{"a":2},"c":[{"a":1},{"a":2}]})"));
  EXPECT_THROW(parse_json_unique(R"({"a":1,"a":2})"), std::invalid_argument);
  EXPECT_THROW(parse_json_unique(R"({"b":{"x":1,"x":1}})"), std::invalid_argument);
  EXPECT_EQ(echo("short"), "short");
  const std::string cut = echo(std::string(3000, 'f'));
  EXPECT_LT(cut.size(), 100u);
  EXPECT_NE(cut.find("3000 bytes"), std::string::npos);
  // Never inside a UTF-8 character: 63 ASCII bytes then a two-byte one.
  const std::string mixed = echo(std::string(63, 'a') + "\xc3\xa9" + std::string(10, 'b'));
  EXPECT_EQ(mixed.substr(0, 64), std::string(63, 'a') + ".");
}

}  // namespace
