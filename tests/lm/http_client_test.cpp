// HttpClient details not covered through the two backends.
#include <gtest/gtest.h>

#include <atomic>
#include <chrono>
#include <thread>
#include <vector>

#include "language/lm/http_client.hpp"
#include "lm/fake_openai_server.hpp"

namespace clips::lm {
namespace {

using namespace std::chrono_literals;

TEST(HttpClientTest, ExtractsTheServersErrorText) {
  EXPECT_EQ(server_error_text(R"({"error":{"message":"bad key","type":"auth"}})"), "bad key");
  EXPECT_EQ(server_error_text(R"({"object":"error","message":"max_tokens must be at least 1"})"),
            "max_tokens must be at least 1");
  EXPECT_EQ(server_error_text(R"({"error":"plain"})"), "plain");
  EXPECT_EQ(server_error_text(R"({"detail":"Not Found"})"), "Not Found");
  EXPECT_EQ(server_error_text(""), "(empty body)");
  EXPECT_EQ(server_error_text(std::string(1000, 'x')).size(), 303u);
}

TEST(HttpClientTest, JoinsUrlsWithoutDoubleSlashes) {
  EXPECT_EQ(join_url("http://h:1/v1/", "/completions"), "http://h:1/v1/completions");
  EXPECT_EQ(join_url("http://h:1/v1", "/completions"), "http://h:1/v1/completions");
}

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

TEST(HttpClientTest, IsUsableFromSeveralThreads) {
  fake::FakeOpenAiServer server;
  server.start();
  HttpOptions o;
  o.total_timeout = 2000ms;
  HttpClient client(o);
  std::vector<std::thread> threads;
  std::atomic<int> ok{0};
  for (int t = 0; t < 4; ++t) {
    threads.emplace_back([&] {
      for (int i = 0; i < 5; ++i) {
        if (client.post_json(server.base_url() + "/chat/completions", R"({"messages":[]})", {}).status == 200) {
          ++ok;
        }
      }
    });
  }
  for (auto& th : threads) th.join();
  EXPECT_EQ(ok.load(), 20);
  EXPECT_EQ(server.chat_requests(), 20);
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

TEST(HttpClientTest, DefaultReplyCapIsSixteenMebibytes) {
  EXPECT_EQ(HttpOptions{}.max_reply_bytes, std::size_t{16} << 20);
}

}  // namespace
}  // namespace clips::lm
