// `clips serve` on loopback against slow, hostile and non-conforming clients
// (issue 46): a busy port, slow header senders, connection bounds, the
// listen backlog, Host/Origin checks, content types, the owner's session
// list, HTTP conformance and language-model failures as gateway errors.
// Every wait is bounded (client timeouts, poll deadlines); none asserts a
// duration.
#include <gtest/gtest.h>
#include <poll.h>
#include <unistd.h>

#include <cstdio>
#include <fstream>
#include <string>
#include <thread>
#include <vector>

#include <httplib.h>
#include <nlohmann/json.hpp>

#include "lm/fake_openai_server.hpp"
#include "serve/server_process.hpp"

namespace {

using nlohmann::json;
using namespace clips::serve::testing;

const std::string kDkg = std::string(CLIPS_SOURCE_DIR) + "/data/examples/doors-keys-gems";

std::string get(const std::string& path, const std::string& extra_headers = "") {
  return "GET " + path + " HTTP/1.1\r\nHost: 127.0.0.1\r\n" + extra_headers + "\r\n";
}

std::string post(const std::string& path, const std::string& body, const std::string& type = "application/json",
                 const std::string& extra_headers = "") {
  return "POST " + path + " HTTP/1.1\r\nHost: 127.0.0.1\r\nContent-Type: " + type +
         "\r\nContent-Length: " + std::to_string(body.size()) + "\r\n" + extra_headers + "\r\n" + body;
}

const std::string kCreate = R"({"dataset":"doors-keys-gems","problem":"e1"})";

TEST(ServeHardening, BusyPortIsAnErrorWithItsOwnExitCode) {
  ServerProcess first({}, {"--dataset", kDkg});
  ASSERT_GT(first.port, 0);
  ServerProcess second({}, {"--dataset", kDkg}, first.port);
  EXPECT_EQ(second.port, -1) << "a second server listened on a port in use";
  EXPECT_EQ(second.wait_exit(), 9);
  EXPECT_NE(second.all_lines().find("already in use"), std::string::npos) << second.all_lines();
  // The first one still answers, and alone.
  httplib::Client cli("127.0.0.1", first.port);
  cli.set_read_timeout(30, 0);
  auto r = cli.Get("/api/health");
  ASSERT_TRUE(r);
  EXPECT_EQ(r->status, 200);
  EXPECT_EQ(first.stop(), 0);
}

TEST(ServeHardening, SlowHeaderSendersNeitherFreezeHealthNorStayForever) {
  ServerProcess server({}, {"--dataset", kDkg, "--threads", "2", "--read-timeout", "2"});
  ASSERT_GT(server.port, 0);
  // Twelve connections (six times --threads) that send half a request line and stop.
  std::vector<int> slow;
  for (int i = 0; i < 12; ++i) {
    const int fd = connect_loopback(server.port);
    ASSERT_GE(fd, 0);
    ASSERT_TRUE(send_all(fd, "GET /api/health HTTP/1.1\r\nHo"));
    slow.push_back(fd);
  }
  httplib::Client cli("127.0.0.1", server.port);
  cli.set_connection_timeout(10, 0);
  cli.set_read_timeout(10, 0);
  auto r = cli.Get("/api/health");
  ASSERT_TRUE(r) << "health did not answer while slow clients were connected";
  EXPECT_EQ(r->status, 200);
  // So is one whose body stops short of its Content-Length.
  const int short_body = connect_loopback(server.port);
  ASSERT_GE(short_body, 0);
  ASSERT_TRUE(send_all(short_body, "POST /api/sessions HTTP/1.1\r\nHost: 127.0.0.1\r\nContent-Type: application/json\r\n"
                                   "Content-Length: 100\r\n\r\n{\"dataset\""));
  slow.push_back(short_body);
  // Each slow connection is answered 408 and closed at its read timeout.
  for (int fd : slow) {
    const std::string reply = read_until_closed(fd, 30);
    EXPECT_EQ(raw_status(reply), 408) << reply;
    close(fd);
  }
  EXPECT_EQ(server.stop(), 0);
}

TEST(ServeHardening, ConnectionsPerClientAreBounded) {
  ServerProcess server({}, {"--dataset", kDkg, "--max-client-connections", "4", "--read-timeout", "60"});
  ASSERT_GT(server.port, 0);
  // Four connections busy with a request: their heads have arrived, their
  // bodies are still on the way. A connection of the test harness's own
  // (its readiness probe) may still be counted while they arrive, so one of
  // them can be turned away: open another in its place.
  const std::string slow_post = "POST /api/sessions HTTP/1.1\r\nHost: 127.0.0.1\r\nContent-Type: application/json\r\n"
                                "Content-Length: 100\r\n\r\n{";
  std::vector<int> busy;
  for (int tries = 0; tries < 12 && busy.size() < 4; ++tries) {
    const int fd = connect_loopback(server.port);
    ASSERT_GE(fd, 0);
    ASSERT_TRUE(send_all(fd, slow_post));
    pollfd p{fd, POLLIN, 0};
    if (poll(&p, 1, 200) == 0) {
      busy.push_back(fd);  // nothing came back: held open, reading the body
    } else {
      close(fd);  // answered (503) and closed
    }
  }
  ASSERT_EQ(busy.size(), 4u);
  // A fifth is turned away once the server has taken the four (it accepts
  // them on its own threads: ask a few times).
  std::string reply;
  for (int attempt = 0; attempt < 50 && raw_status(reply) != 503; ++attempt) {
    reply = raw_exchange(server.port, get("/api/health"), 30);
    if (raw_status(reply) != 503) std::this_thread::sleep_for(std::chrono::milliseconds(100));
  }
  EXPECT_EQ(raw_status(reply), 503) << reply;
  EXPECT_NE(raw_body(reply).find("--max-client-connections"), std::string::npos) << reply;
  for (int fd : busy) close(fd);
  // With the four gone, requests are served again.
  for (int attempt = 0; attempt < 50 && raw_status(reply) != 200; ++attempt) {
    reply = raw_exchange(server.port, get("/api/health"), 30);
    if (raw_status(reply) != 200) std::this_thread::sleep_for(std::chrono::milliseconds(100));
  }
  EXPECT_EQ(raw_status(reply), 200) << reply;
  // Idle connections (no head yet) do not lock the address out (issue 61):
  // the oldest is dropped for a newcomer, which is served.
  std::vector<int> idle;
  for (int i = 0; i < 4; ++i) {
    idle.push_back(connect_loopback(server.port));
    ASSERT_TRUE(send_all(idle.back(), "GET /api/health HTTP/1.1\r\n"));  // and nothing more
  }
  std::this_thread::sleep_for(std::chrono::milliseconds(300));
  reply = raw_exchange(server.port, get("/api/health"), 30);
  EXPECT_EQ(raw_status(reply), 200) << reply;
  EXPECT_EQ(read_until_closed(idle.front(), 5), "");  // closed without a reply
  for (int fd : idle) close(fd);
  EXPECT_EQ(server.stop(), 0);
}

TEST(ServeHardening, ListenBacklogIsLarge) {
  ServerProcess server({}, {"--dataset", kDkg});
  ASSERT_GT(server.port, 0);
  // `ss` shows a listening socket's backlog as its Send-Q.
  const std::string cmd = "ss -ltnH 'sport = :" + std::to_string(server.port) + "' 2>/dev/null";
  FILE* p = popen(cmd.c_str(), "r");
  ASSERT_NE(p, nullptr);
  char line[512] = "";
  const bool got = fgets(line, sizeof line, p) != nullptr;
  pclose(p);
  if (!got) GTEST_SKIP() << "ss (iproute2) is not available";
  char state[32];
  int recv_q = 0, send_q = 0;
  ASSERT_EQ(sscanf(line, "%31s %d %d", state, &recv_q, &send_q), 3) << line;
  EXPECT_GE(send_q, 128) << line;
  // A burst of 100 connections is accepted and answered.
  std::vector<int> fds;
  for (int i = 0; i < 100; ++i) {
    const int fd = connect_loopback(server.port);
    ASSERT_GE(fd, 0) << "connection " << i;
    send_all(fd, get("/api/health"));
    fds.push_back(fd);
  }
  int answered = 0;
  for (int fd : fds) {
    const std::string reply = read_until_closed(fd, 60);
    answered += raw_status(reply) == 200 || raw_status(reply) == 503;
    close(fd);
  }
  EXPECT_EQ(answered, 100);
  EXPECT_EQ(server.stop(), 0);
}

TEST(ServeHardening, HostAndOriginChecks) {
  ServerProcess server({}, {"--dataset", kDkg, "--allow-origin", "https://app.example.org"});
  ASSERT_GT(server.port, 0);
  const int port = server.port;
  const std::string self = "127.0.0.1:" + std::to_string(port);
  // DNS rebinding: the page's own name in Host.
  std::string r = raw_exchange(port, "GET /api/health HTTP/1.1\r\nHost: attacker.example:" + std::to_string(port) + "\r\n\r\n");
  EXPECT_EQ(raw_status(r), 403) << r;
  EXPECT_NE(raw_body(r).find("DNS-rebinding"), std::string::npos) << r;
  r = raw_exchange(port, "GET /api/health HTTP/1.1\r\nHost: localhost:" + std::to_string(port) + "\r\n\r\n");
  EXPECT_EQ(raw_status(r), 200) << r;
  // Another web site's page may not create sessions (neither as JSON nor as a
  // form-free text/plain "simple" request).
  r = raw_exchange(port, post("/api/sessions", kCreate, "application/json", "Origin: https://evil.example\r\n"));
  EXPECT_EQ(raw_status(r), 403) << r;
  r = raw_exchange(port, post("/api/sessions", kCreate, "text/plain", "Origin: https://evil.example\r\n"));
  EXPECT_EQ(raw_status(r), 403) << r;
  r = raw_exchange(port, post("/api/sessions", kCreate, "text/plain"));
  EXPECT_EQ(raw_status(r), 415) << r;
  r = raw_exchange(port, post("/api/sessions", kCreate, "application/json", "Origin: null\r\n"));
  EXPECT_EQ(raw_status(r), 403) << r;
  // The page itself, pages on loopback and --allow-origin may.
  r = raw_exchange(port, "POST /api/sessions HTTP/1.1\r\nHost: " + self + "\r\nOrigin: http://" + self +
                             "\r\nContent-Type: application/json; charset=utf-8\r\nContent-Length: " +
                             std::to_string(kCreate.size()) + "\r\n\r\n" + kCreate);
  EXPECT_EQ(raw_status(r), 201) << r;
  EXPECT_EQ(raw_header(r, "Access-Control-Allow-Origin"), "");
  r = raw_exchange(port, post("/api/sessions", kCreate, "application/json", "Origin: http://localhost:3000\r\n"));
  EXPECT_EQ(raw_status(r), 201) << r;
  EXPECT_EQ(raw_header(r, "Access-Control-Allow-Origin"), "http://localhost:3000");
  r = raw_exchange(port, "OPTIONS /api/sessions HTTP/1.1\r\nHost: " + self +
                             "\r\nOrigin: https://app.example.org\r\nAccess-Control-Request-Method: POST\r\n"
                             "Access-Control-Request-Headers: content-type\r\n\r\n");
  EXPECT_EQ(raw_status(r), 204) << r;
  EXPECT_EQ(raw_header(r, "Access-Control-Allow-Origin"), "https://app.example.org");
  EXPECT_NE(raw_header(r, "Access-Control-Allow-Headers").find("Content-Type"), std::string::npos) << r;
  r = raw_exchange(port, post("/api/sessions", kCreate, "application/json", "Origin: https://app.example.org\r\n"));
  EXPECT_EQ(raw_status(r), 201) << r;
  EXPECT_EQ(raw_header(r, "Access-Control-Allow-Origin"), "https://app.example.org");
  EXPECT_EQ(server.stop(), 0);
}

TEST(ServeHardening, OwnerListsAndDeletesEverySession) {
  ServerProcess server({}, {"--dataset", kDkg});
  ASSERT_GT(server.port, 0);
  ASSERT_GE(server.token.size(), 16u) << server.all_lines();
  httplib::Client cli("127.0.0.1", server.port);
  cli.set_read_timeout(60, 0);
  for (int i = 0; i < 3; ++i) {
    auto r = cli.Post("/api/sessions", kCreate, "application/json");
    ASSERT_TRUE(r);
    ASSERT_EQ(r->status, 201) << r->body;
  }
  auto r = cli.Get("/api/sessions");
  ASSERT_TRUE(r);
  EXPECT_EQ(r->status, 401);
  EXPECT_EQ(r->get_header_value("WWW-Authenticate"), "Bearer");
  r = cli.Get("/api/sessions", {{"Authorization", "Bearer wrong-token-0123456789abcdef"}});
  ASSERT_TRUE(r);
  EXPECT_EQ(r->status, 401);
  r = cli.Delete("/api/sessions");
  ASSERT_TRUE(r);
  EXPECT_EQ(r->status, 401);
  const httplib::Headers owner = {{"Authorization", "Bearer " + server.token}};
  r = cli.Get("/api/sessions", owner);
  ASSERT_TRUE(r);
  ASSERT_EQ(r->status, 200) << r->body;
  const json list = json::parse(r->body);
  ASSERT_EQ(list["sessions"].size(), 3u);
  EXPECT_EQ(list["sessions"][0]["dataset"], "doors-keys-gems");
  EXPECT_EQ(list["sessions"][0]["problem"], "e1");
  EXPECT_EQ(list["sessions"][0]["method"], "clips");
  r = cli.Delete("/api/sessions", owner);
  ASSERT_TRUE(r);
  ASSERT_EQ(r->status, 200) << r->body;
  EXPECT_EQ(json::parse(r->body)["deleted"].size(), 3u);
  r = cli.Get("/api/health");
  ASSERT_TRUE(r);
  EXPECT_EQ(json::parse(r->body)["sessions"], 0);
  EXPECT_EQ(server.stop(), 0);
}

TEST(ServeHardening, OwnerTokenFromAFile) {
  char path[] = "/tmp/clips-owner-XXXXXX";
  const int fd = mkstemp(path);
  ASSERT_GE(fd, 0);
  close(fd);
  std::ofstream(path) << "short\n";
  ServerProcess bad({}, {"--dataset", kDkg, "--owner-token-file", path});
  EXPECT_EQ(bad.port, -1);
  EXPECT_EQ(bad.wait_exit(), 3);
  std::ofstream(path) << "0123456789abcdef-owner\n";
  ServerProcess server({}, {"--dataset", kDkg, "--owner-token-file", path});
  ASSERT_GT(server.port, 0);
  std::remove(path);
  EXPECT_EQ(server.token, "0123456789abcdef-owner");
  httplib::Client cli("127.0.0.1", server.port);
  auto r = cli.Get("/api/sessions", {{"Authorization", "Bearer 0123456789abcdef-owner"}});
  ASSERT_TRUE(r);
  EXPECT_EQ(r->status, 200);
  EXPECT_EQ(server.stop(), 0);
}

TEST(ServeHardening, HttpConformance) {
  ServerProcess server({}, {"--dataset", kDkg, "--max-body", "65536"});
  ASSERT_GT(server.port, 0);
  const int port = server.port;
  // POST without Content-Length.
  std::string r = raw_exchange(port, "POST /api/sessions HTTP/1.1\r\nHost: 127.0.0.1\r\nContent-Type: application/json\r\n\r\n");
  EXPECT_EQ(raw_status(r), 411) << r;
  r = raw_exchange(port, "POST /api/sessions HTTP/1.1\r\nHost: 127.0.0.1\r\nTransfer-Encoding: chunked\r\n"
                         "Content-Type: application/json\r\n\r\n2\r\n{}\r\n0\r\n\r\n");
  EXPECT_EQ(raw_status(r), 411) << r;
  // Methods the server does not have: 405 with Allow.
  for (const std::string method : {"PUT", "PATCH", "FOO"}) {
    r = raw_exchange(port, method + " /api/sessions HTTP/1.1\r\nHost: 127.0.0.1\r\nContent-Length: 0\r\n\r\n");
    EXPECT_EQ(raw_status(r), 405) << method << ": " << r;
    EXPECT_EQ(raw_header(r, "Allow"), "GET, HEAD, POST, DELETE, OPTIONS") << r;
  }
  r = raw_exchange(port, "OPTIONS / HTTP/1.1\r\nHost: 127.0.0.1\r\n\r\n");
  EXPECT_EQ(raw_status(r), 204) << r;
  EXPECT_EQ(raw_header(r, "Allow"), "GET, HEAD, OPTIONS") << r;
  r = raw_exchange(port, "POST / HTTP/1.1\r\nHost: 127.0.0.1\r\nContent-Length: 0\r\n\r\n");
  EXPECT_EQ(raw_status(r), 405) << r;
  EXPECT_EQ(raw_header(r, "Allow"), "GET, HEAD, OPTIONS") << r;
  r = raw_exchange(port, get("/api/sessions/0123/act"));
  EXPECT_EQ(raw_status(r), 405) << r;
  EXPECT_EQ(raw_header(r, "Allow"), "POST, OPTIONS") << r;
  // HEAD is GET without the body.
  r = raw_exchange(port, "HEAD / HTTP/1.1\r\nHost: 127.0.0.1\r\n\r\n");
  EXPECT_EQ(raw_status(r), 200) << r;
  EXPECT_EQ(raw_body(r), "");
  // Oversized request line and header.
  r = raw_exchange(port, get("/" + std::string(10000, 'a')));
  EXPECT_EQ(raw_status(r), 414) << r.substr(0, 200);
  r = raw_exchange(port, get("/api/health", "X-Big: " + std::string(100000, 'b') + "\r\n"));
  EXPECT_EQ(raw_status(r), 431) << r.substr(0, 200);
  // A body over the limit, whatever its type, names the real limit.
  r = raw_exchange(port, "POST /api/sessions HTTP/1.1\r\nHost: 127.0.0.1\r\nContent-Type: application/x-www-form-urlencoded\r\n"
                         "Content-Length: 70000\r\n\r\n" + std::string(70000, 'a'));
  EXPECT_EQ(raw_status(r), 413) << r.substr(0, 300);
  EXPECT_NE(raw_body(r).find("70000 bytes exceeds the limit of 65536"), std::string::npos) << raw_body(r);
  r = raw_exchange(port, post("/api/sessions", "a=" + std::string(9000, 'a'), "application/x-www-form-urlencoded"));
  EXPECT_EQ(raw_status(r), 415) << r.substr(0, 300);
  // Duplicate keys.
  r = raw_exchange(port, post("/api/sessions", R"({"dataset":"doors-keys-gems","problem":"e1","problem":"e2"})"));
  EXPECT_EQ(raw_status(r), 400) << r;
  EXPECT_NE(raw_body(r).find("duplicate key 'problem'"), std::string::npos) << r;
  // A long id is not echoed in full.
  const std::string long_id(3000, 'f');
  r = raw_exchange(port, get("/api/sessions/" + long_id));
  EXPECT_EQ(raw_status(r), 404) << r.substr(0, 300);
  EXPECT_LT(raw_body(r).size(), 300u) << raw_body(r).substr(0, 300);
  EXPECT_NE(raw_body(r).find("3000 bytes"), std::string::npos) << raw_body(r).substr(0, 300);
  // Malformed request line.
  r = raw_exchange(port, "GET /api/health\r\n\r\n");
  EXPECT_EQ(raw_status(r), 400) << r;
  EXPECT_EQ(server.stop(), 0);
}

// A failing language model is another server failing behind this one: 502,
// or 504 when it timed out.
TEST(ServeHardening, LanguageModelFailuresAreGatewayErrors) {
  clips::lm::fake::FakeOpenAiServer lm;
  lm.start();
  ServerProcess server({"OPENAI_API_KEY=test"}, {"--dataset", kDkg, "--lm", "openai", "--lm-base-url",
                                                 lm.base_url(), "--lm-timeout", "0.3"});
  ASSERT_GT(server.port, 0);
  httplib::Client cli("127.0.0.1", server.port);
  cli.set_read_timeout(60, 0);
  auto r = cli.Post("/api/sessions", kCreate, "application/json");
  ASSERT_TRUE(r);
  ASSERT_EQ(r->status, 201) << r->body;
  const std::string url = "/api/sessions/" + json::parse(r->body)["id"].get<std::string>();
  clips::lm::fake::FakeFaults faults;
  faults.reply = clips::lm::fake::FakeReply::MalformedJson;
  lm.set_faults(faults);
  r = cli.Post((url + "/hear").c_str(), R"({"utterance":"Can you get me the yellow key?"})", "application/json");
  ASSERT_TRUE(r);
  EXPECT_EQ(r->status, 502) << r->body;
  faults = {};
  faults.delay_ms = 2000;
  lm.set_faults(faults);
  r = cli.Post((url + "/hear").c_str(), R"({"utterance":"Can you get me the yellow key?"})", "application/json");
  ASSERT_TRUE(r);
  EXPECT_EQ(r->status, 504) << r->body;
  EXPECT_EQ(server.stop(), 0);
  lm.stop();
}

}  // namespace
