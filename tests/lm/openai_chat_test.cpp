// OpenAiChatClient and the base64 encoder against the loopback fake server.
#include <gtest/gtest.h>

#include <chrono>
#include <nlohmann/json.hpp>

#include "lm/base64.hpp"
#include "lm/openai_chat.hpp"
#include "lm/fake_openai_server.hpp"

namespace clips::lm {
namespace {

using fake::FakeFaults;
using fake::FakeOpenAiServer;
using fake::FakeReply;
using nlohmann::json;
using namespace std::chrono_literals;

// A real 1x1 PNG (signature, IHDR, IDAT, IEND).
const std::vector<std::uint8_t> kPng = {
    0x89, 0x50, 0x4E, 0x47, 0x0D, 0x0A, 0x1A, 0x0A, 0x00, 0x00, 0x00, 0x0D, 0x49, 0x48, 0x44, 0x52,
    0x00, 0x00, 0x00, 0x01, 0x00, 0x00, 0x00, 0x01, 0x08, 0x06, 0x00, 0x00, 0x00, 0x1F, 0x15, 0xC4,
    0x89, 0x00, 0x00, 0x00, 0x0D, 0x49, 0x44, 0x41, 0x54, 0x78, 0x9C, 0x63, 0xF8, 0xCF, 0xC0, 0xF0,
    0x1F, 0x00, 0x05, 0x00, 0x01, 0xFF, 0x89, 0x99, 0x3D, 0x1D, 0x00, 0x00, 0x00, 0x00, 0x49, 0x45,
    0x4E, 0x44, 0xAE, 0x42, 0x60, 0x82};

class OpenAiChatTest : public ::testing::Test {
 protected:
  void SetUp() override { server.start(); }
  void TearDown() override { server.stop(); }

  OpenAiChatOptions options() const {
    OpenAiChatOptions o;
    o.base_url = server.base_url();
    o.model = "fake-vision";
    o.api_key = "";
    o.http.connect_timeout = 200ms;
    o.http.total_timeout = 500ms;
    o.http.max_retries = 2;
    o.http.backoff_initial = 5ms;
    return o;
  }
  std::string url() const { return server.base_url() + "/chat/completions"; }

  static ChatRequest request(bool json_object = true) {
    ChatRequest r;
    r.messages.push_back({"system", {ChatPart::from_text("You infer goals.")}});
    r.messages.push_back({"user", {ChatPart::from_text("Which gem?"), ChatPart::from_png(kPng, "low")}});
    r.temperature = 0.0;
    r.max_tokens = 64;
    r.json_object = json_object;
    return r;
  }

  std::string error_of(OpenAiChatClient& c, const ChatRequest& r) {
    try {
      c.complete(r);
    } catch (const LmError& e) {
      return e.what();
    }
    return "";
  }

  FakeOpenAiServer server;
};

TEST_F(OpenAiChatTest, SendsTextAndImagePartsAndReturnsTheAnswer) {
  OpenAiChatClient client(options());
  const json answer = json::parse(client.complete(request()));
  EXPECT_EQ(answer["model"], "fake-vision");
  EXPECT_EQ(answer["text"], "You infer goals.\nWhich gem?\n");
  EXPECT_EQ(answer["images"], 1);
  EXPECT_EQ(answer["images_valid"], true);
  EXPECT_EQ(answer["json_mode"], true);

  const json body = server.last_chat_body();
  EXPECT_EQ(body["model"], "fake-vision");
  EXPECT_DOUBLE_EQ(body["temperature"].get<double>(), 0.0);
  EXPECT_EQ(body["max_tokens"], 64);
  EXPECT_EQ(body["response_format"]["type"], "json_object");
  const json& image = body["messages"][1]["content"][1];
  EXPECT_EQ(image["type"], "image_url");
  EXPECT_EQ(image["image_url"]["detail"], "low");
  const std::string url = image["image_url"]["url"];
  const std::string prefix = "data:image/png;base64,";
  ASSERT_EQ(url.rfind(prefix, 0), 0u) << url;
  auto decoded = base64_decode(std::string_view(url).substr(prefix.size()));
  ASSERT_TRUE(decoded.has_value());
  EXPECT_EQ(*decoded, kPng);
  EXPECT_EQ(url, png_data_url(kPng));
}

TEST_F(OpenAiChatTest, OmitsOptionalFieldsWhenUnset) {
  OpenAiChatClient client(options());
  ChatRequest r;
  r.messages.push_back({"user", {ChatPart::from_text("hi")}});
  const json answer = json::parse(client.complete(r));
  EXPECT_EQ(answer["json_mode"], false);
  const json body = server.last_chat_body();
  EXPECT_FALSE(body.contains("temperature"));
  EXPECT_FALSE(body.contains("max_tokens"));
  EXPECT_FALSE(body.contains("response_format"));
}

TEST_F(OpenAiChatTest, AnswerThatIsNotJsonIsAnErrorOnlyInJsonMode) {
  FakeFaults f;
  f.reply = FakeReply::NonJsonAnswer;
  server.set_faults(f);
  OpenAiChatClient client(options());
  const std::string msg = error_of(client, request(true));
  EXPECT_NE(msg.find("reply from " + url() + ": choices[0].message.content is not valid JSON"),
            std::string::npos)
      << msg;
  EXPECT_NE(msg.find("finish_reason stop"), std::string::npos) << msg;
  auto lenient = request(true);
  lenient.validate_json = false;
  EXPECT_EQ(client.complete(lenient), "Sure! Here it is: {oops");
  EXPECT_EQ(client.complete(request(false)), "Sure! Here it is: {oops");
}

TEST_F(OpenAiChatTest, EveryMalformedReplyNamesTheField) {
  const std::vector<std::pair<FakeReply, std::string>> cases = {
      {FakeReply::MalformedJson, "body is not valid JSON"},
      {FakeReply::CutJson, "body is not valid JSON"},
      {FakeReply::MissingChoices, "choices missing"},
      {FakeReply::MissingContent, "choices[0].message.content missing (refusal: I cannot help with that.)"},
  };
  for (const auto& [reply, expected] : cases) {
    FakeFaults f;
    f.reply = reply;
    server.set_faults(f);
    OpenAiChatClient client(options());
    const std::string msg = error_of(client, request());
    EXPECT_NE(msg.find("reply from " + url() + ": " + expected), std::string::npos) << msg;
  }
}

TEST_F(OpenAiChatTest, RetriesThenSucceedsAndGivesUpAfterBudget) {
  FakeFaults f;
  f.fail_first = 2;
  f.fail_status = 429;
  f.retry_after = "0";
  server.set_faults(f);
  OpenAiChatClient client(options());
  EXPECT_NO_THROW(client.complete(request()));
  EXPECT_EQ(server.chat_requests(), 3);

  f.fail_first = 10;
  f.fail_status = 502;
  f.retry_after = "";
  server.set_faults(f);
  const std::string msg = error_of(client, request());
  EXPECT_NE(msg.find("POST " + url() + ": HTTP 502 after 3 attempts, retry budget exhausted"),
            std::string::npos)
      << msg;
  EXPECT_EQ(server.chat_requests(), 6);
}

TEST_F(OpenAiChatTest, TimeoutAndTruncatedTransfer) {
  FakeFaults f;
  f.delay_ms = 800;
  server.set_faults(f);
  auto o = options();
  o.http.total_timeout = 120ms;
  o.http.max_retries = 0;
  OpenAiChatClient slow(o);
  std::string msg = error_of(slow, request());
  EXPECT_NE(msg.find("POST " + url() + " timed out after 1 attempt"), std::string::npos) << msg;

  f = FakeFaults{};
  f.reply = FakeReply::ShortBody;
  server.set_faults(f);
  OpenAiChatClient client(options());
  msg = error_of(client, request());
  EXPECT_NE(msg.find("failed after 3 attempts"), std::string::npos) << msg;
  EXPECT_NE(msg.find("curl error 18"), std::string::npos) << msg;
}

TEST_F(OpenAiChatTest, AuthorizationHeaderIffKeySetAndEnvDefaults) {
  auto o = options();
  o.api_key = "sk-chat";
  OpenAiChatClient(o).complete(request());
  o.api_key = "";
  OpenAiChatClient(o).complete(request());
  const auto headers = server.authorization_headers();
  ASSERT_EQ(headers.size(), 2u);
  EXPECT_EQ(headers[0], std::optional<std::string>("Bearer sk-chat"));
  EXPECT_FALSE(headers[1].has_value());

  OpenAiChatOptions defaults;
  defaults.api_key = "";
  if (std::getenv("CLIPS_CHAT_BASE_URL") == nullptr && std::getenv("CLIPS_CHAT_MODEL") == nullptr) {
    OpenAiChatClient c(defaults);
    EXPECT_EQ(c.endpoint(), "https://api.openai.com/v1/chat/completions");
    EXPECT_EQ(c.model(), "gpt-4o");
  }
}

TEST(ChatBase64Test, MatchesRfc4648Vectors) {
  const std::vector<std::pair<std::string, std::string>> vectors = {
      {"", ""},         {"f", "Zg=="},         {"fo", "Zm8="},         {"foo", "Zm9v"},
      {"foob", "Zm9vYg=="}, {"fooba", "Zm9vYmE="}, {"foobar", "Zm9vYmFy"}};
  for (const auto& [plain, encoded] : vectors) {
    EXPECT_EQ(base64_encode(std::string_view(plain)), encoded);
    auto back = base64_decode(encoded);
    ASSERT_TRUE(back.has_value()) << encoded;
    EXPECT_EQ(std::string(back->begin(), back->end()), plain);
  }
}

TEST(ChatBase64Test, RoundTripsAllByteValuesAndRejectsGarbage) {
  std::vector<std::uint8_t> all;
  for (int i = 0; i < 256; ++i) all.push_back(static_cast<std::uint8_t>(255 - i));
  for (std::size_t n = 0; n <= all.size(); n += 37) {
    std::vector<std::uint8_t> part(all.begin(), all.begin() + static_cast<std::ptrdiff_t>(n));
    auto back = base64_decode(base64_encode(std::span<const std::uint8_t>(part)));
    ASSERT_TRUE(back.has_value());
    EXPECT_EQ(*back, part);
  }
  EXPECT_EQ(base64_encode(std::string_view("\xff\xfe\xfd")), "//79");
  EXPECT_FALSE(base64_decode("Zm9").has_value());     // length
  EXPECT_FALSE(base64_decode("Zm9v!A==").has_value());  // alphabet
  EXPECT_FALSE(base64_decode("Z===").has_value());    // padding
  EXPECT_FALSE(base64_decode("Zg==Zm9v").has_value());  // padding in the middle
}

}  // namespace
}  // namespace clips::lm
