#include "lm/http_client_test.hpp"

namespace clips::lm {
namespace http_client_test {
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

TEST(HttpClientTest, DefaultReplyCapIsSixteenMebibytes) {
  EXPECT_EQ(HttpOptions{}.max_reply_bytes, std::size_t{16} << 20);
}

}  // namespace http_client_test

}  // namespace clips::lm
