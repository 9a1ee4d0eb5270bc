#include "lm/http_client_test.hpp"

namespace clips::lm {
namespace http_client_test {
TEST(HttpClientTest, ReturnsNonRetryableStatusesWithoutRetrying) {
  fake::FakeOpenAiServer server;
  server.start();
  HttpOptions o;
  o.total_timeout = 500ms;
  o.backoff_initial = 1ms;
  HttpClient client(o);
  auto r = client.post_json(server.base_url() + "/nowhere", "{}", {});
  EXPECT_EQ(r.status, 404);
  EXPECT_EQ(r.attempts, 1);

  fake::FakeFaults f;
  f.fail_first = 1;
  f.fail_status = 500;
  f.retry_after = "0";
  server.set_faults(f);
  r = client.post_json(server.base_url() + "/chat/completions", R"({"messages":[]})", {});
  EXPECT_EQ(r.status, 200);
  EXPECT_EQ(r.attempts, 2);
  EXPECT_EQ(r.headers.count("content-type"), 1u);
  server.stop();
}

// A server that streams without end is cut off at the reply cap with an error
// naming the URL and the cap, after one attempt (retrying would stream again).
TEST(HttpClientTest, StopsReadingAnEndlessReplyAtTheCap) {
  fake::FakeOpenAiServer server;
  server.start();
  fake::FakeFaults f;
  f.reply = fake::FakeReply::Endless;
  server.set_faults(f);
  HttpOptions o;
  o.total_timeout = 20000ms;  // far longer than reading the cap takes
  o.backoff_initial = 1ms;
  o.max_reply_bytes = std::size_t{1} << 20;
  HttpClient client(o);
  const std::string url = server.base_url() + "/completions";
  const auto t0 = std::chrono::steady_clock::now();
  try {
    client.post_json(url, R"({"prompt":"x"})", {});
    FAIL() << "an endless reply was accepted";
  } catch (const LmError& e) {
    const std::string msg = e.what();
    EXPECT_NE(msg.find(url), std::string::npos) << msg;
    EXPECT_NE(msg.find("1048576 bytes"), std::string::npos) << msg;
  }
  EXPECT_LT(std::chrono::steady_clock::now() - t0, 15s);
  EXPECT_EQ(server.completion_requests(), 1);
  server.stop();
}

}  // namespace http_client_test

}  // namespace clips::lm
