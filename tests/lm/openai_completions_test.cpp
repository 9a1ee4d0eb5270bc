#include "lm/openai_completions_test.hpp"

namespace clips::lm {
namespace openai_completions_test {
TEST_F(OpenAiCompletionsTest, SumsExactlyTheContinuationTokensIncludingNewline) {
  OpenAiCompletionsModel m(options());
  auto scores = m.score({{kPrompt, kUtterance}});
  ASSERT_EQ(scores.size(), 1u);

  // By hand: " Can" " you" " pass" " me" " the" " red" " key" "?" "\n".
  double by_hand = 0;
  for (const char* t : {" Can", " you", " pass", " me", " the", " red", " key", "?", "\n"}) {
    by_hand += FakeOpenAiServer::unigram_logprob(t);
  }
  EXPECT_NEAR(scores[0], by_hand, 1e-9);
  EXPECT_NEAR(scores[0], expected_sum(kPrompt, kUtterance), 1e-9);
  // Without the "\n" stop token the score would differ.
  EXPECT_GT(std::abs(scores[0] - (by_hand - FakeOpenAiServer::unigram_logprob("\n"))), 1e-3);

  const json body = server.last_completion_body();
  EXPECT_EQ(body["echo"], true);
  EXPECT_EQ(body["max_tokens"], 0);
  EXPECT_EQ(body["model"], "fake-model");
  EXPECT_EQ(body["prompt"][0], kPrompt + kUtterance);
  EXPECT_EQ(m.name(), "openai:fake-model");
}

TEST_F(OpenAiCompletionsTest, PluggedScorerTotalIsReproducedExactly) {
  server.set_scorer([](const std::string& prompt, const std::string& continuation) {
    return -0.125 * static_cast<double>(continuation.size()) - 0.001 * static_cast<double>(prompt.size());
  });
  OpenAiCompletionsModel m(options());
  auto scores = m.score({{kPrompt, kUtterance}, {kPrompt, " Hand me that key.\n"}});
  EXPECT_NEAR(scores[0], -0.125 * kUtterance.size() - 0.001 * kPrompt.size(), 1e-9);
  EXPECT_NEAR(scores[1], -0.125 * 19 - 0.001 * kPrompt.size(), 1e-9);
}

TEST_F(OpenAiCompletionsTest, EmptyCommandPromptIsScored) {
  OpenAiCompletionsModel m(options());
  auto scores = m.score({{"\n", kUtterance}});
  EXPECT_NEAR(scores[0], expected_sum("\n", kUtterance), 1e-9);
  EXPECT_TRUE(m.score({}).empty());
  EXPECT_EQ(server.completion_requests(), 1);  // an empty batch sends nothing
}

TEST_F(OpenAiCompletionsTest, ScoresAreDividedByTemperature) {
  auto o = options();
  o.temperature = 0.5;
  OpenAiCompletionsModel m(o);
  EXPECT_NEAR(m.score({{kPrompt, kUtterance}})[0], 2.0 * expected_sum(kPrompt, kUtterance), 1e-9);
  EXPECT_DOUBLE_EQ(server.last_completion_body()["temperature"].get<double>(), 0.5);
  o.temperature = 0.0;
  EXPECT_THROW(OpenAiCompletionsModel{o}, LmError);
}

TEST_F(OpenAiCompletionsTest, BatchesSeveralPromptsPerRequestInOrder) {
  auto o = options();
  o.batch_size = 16;
  OpenAiCompletionsModel m(o);
  std::vector<ScoreRequest> batch;
  for (int i = 0; i < 40; ++i) {
    batch.push_back({kPrompt + " (item" + std::to_string(i) + ")\nOutput:", kUtterance});
  }
  batch.push_back(batch[3]);  // a duplicate is sent once
  auto scores = m.score(batch);
  ASSERT_EQ(scores.size(), batch.size());
  EXPECT_EQ(server.completion_requests(), 3);
  EXPECT_EQ(server.prompts_per_request(), (std::vector<std::size_t>{16, 16, 8}));
  for (std::size_t i = 0; i < batch.size(); ++i) {
    EXPECT_NEAR(scores[i], expected_sum(batch[i].prompt, batch[i].continuation), 1e-9) << i;
  }
}

TEST_F(OpenAiCompletionsTest, ChoicesOutOfOrderAreMatchedByIndex) {
  FakeFaults f;
  f.reverse_choices = true;
  server.set_faults(f);
  OpenAiCompletionsModel m(options());
  std::vector<ScoreRequest> batch = {{kPrompt, " A.\n"}, {kPrompt, " Bb bb?\n"}, {"\n", " Ccc ccc ccc!\n"}};
  auto scores = m.score(batch);
  for (std::size_t i = 0; i < batch.size(); ++i) {
    EXPECT_NEAR(scores[i], expected_sum(batch[i].prompt, batch[i].continuation), 1e-9) << i;
  }
}

TEST_F(OpenAiCompletionsTest, FallsBackToOneGeneratedTokenWhenZeroIsRejected) {
  FakeFaults f;
  f.reject_max_tokens_zero = true;
  server.set_faults(f);
  OpenAiCompletionsModel m(options());
  EXPECT_FALSE(m.using_max_tokens_fallback());
  auto s1 = m.score({{kPrompt, kUtterance}});
  EXPECT_TRUE(m.using_max_tokens_fallback());
  EXPECT_EQ(server.completion_requests(), 2);  // rejected once, then max_tokens=1
  EXPECT_EQ(server.last_completion_body()["max_tokens"], 1);
  // The generated token is not part of the score.
  EXPECT_NEAR(s1[0], expected_sum(kPrompt, kUtterance), 1e-9);
  // The fallback is remembered: the next call needs one request only.
  auto s2 = m.score({{kPrompt, " Hand me that key.\n"}});
  EXPECT_EQ(server.completion_requests(), 3);
  EXPECT_NEAR(s2[0], expected_sum(kPrompt, " Hand me that key.\n"), 1e-9);
}

TEST_F(OpenAiCompletionsTest, GeneratedTokensAreIgnoredWhenStartingWithOne) {
  auto o = options();
  o.try_max_tokens_zero = false;
  OpenAiCompletionsModel m(o);
  EXPECT_NEAR(m.score({{kPrompt, kUtterance}})[0], expected_sum(kPrompt, kUtterance), 1e-9);
  EXPECT_EQ(server.last_completion_body()["max_tokens"], 1);
  EXPECT_EQ(server.completion_requests(), 1);
}

TEST_F(OpenAiCompletionsTest, RetriesTransient429And500ThenSucceeds) {
  for (int status : {429, 500, 503}) {
    FakeFaults f;
    f.fail_first = 2;
    f.fail_status = status;
    f.retry_after = status == 429 ? "0" : "";
    server.set_faults(f);
    const int before = server.completion_requests();
    OpenAiCompletionsModel m(options());  // max_retries = 2
    EXPECT_NEAR(m.score({{kPrompt, kUtterance}})[0], expected_sum(kPrompt, kUtterance), 1e-9) << status;
    EXPECT_EQ(server.completion_requests() - before, 3) << status;
  }
}

TEST_F(OpenAiCompletionsTest, HonoursRetryAfterUpToTheCap) {
  FakeFaults f;
  f.fail_first = 1;
  f.fail_status = 429;
  f.retry_after = "1";  // one second, capped to 200 ms below
  server.set_faults(f);
  auto o = options();
  o.http.retry_after_max = 200ms;
  OpenAiCompletionsModel m(o);
  auto t0 = std::chrono::steady_clock::now();
  m.score({{kPrompt, kUtterance}});
  auto elapsed = std::chrono::steady_clock::now() - t0;
  EXPECT_GE(elapsed, 190ms);
  EXPECT_LT(elapsed, 900ms);
}

TEST_F(OpenAiCompletionsTest, GivesUpAfterTheRetryBudgetWithAClearMessage) {
  FakeFaults f;
  f.fail_first = 100;
  f.fail_status = 503;
  server.set_faults(f);
  OpenAiCompletionsModel m(options());
  const std::string msg = error_of(m, {{kPrompt, kUtterance}});
  EXPECT_NE(msg.find(url()), std::string::npos) << msg;
  EXPECT_NE(msg.find("HTTP 503"), std::string::npos) << msg;
  EXPECT_NE(msg.find("3 attempts"), std::string::npos) << msg;
  EXPECT_NE(msg.find("retry budget"), std::string::npos) << msg;
  EXPECT_NE(msg.find("injected failure"), std::string::npos) << msg;  // the server's own text
  EXPECT_EQ(server.completion_requests(), 3);
}

TEST_F(OpenAiCompletionsTest, OtherHttpErrorsAreNotRetried) {
  FakeFaults f;
  f.fail_first = 1;
  f.fail_status = 401;
  server.set_faults(f);
  OpenAiCompletionsModel m(options());
  const std::string msg = error_of(m, {{kPrompt, kUtterance}});
  EXPECT_NE(msg.find("HTTP 401"), std::string::npos) << msg;
  EXPECT_NE(msg.find(url()), std::string::npos) << msg;
  EXPECT_EQ(server.completion_requests(), 1);
}

TEST_F(OpenAiCompletionsTest, TimesOutWithAClearMessage) {
  FakeFaults f;
  f.delay_ms = 800;
  server.set_faults(f);
  auto o = options();
  o.http.total_timeout = 150ms;
  o.http.max_retries = 0;
  OpenAiCompletionsModel m(o);
  auto t0 = std::chrono::steady_clock::now();
  const std::string msg = error_of(m, {{kPrompt, kUtterance}});
  EXPECT_LT(std::chrono::steady_clock::now() - t0, 600ms);
  EXPECT_NE(msg.find("timed out"), std::string::npos) << msg;
  EXPECT_NE(msg.find("150 ms"), std::string::npos) << msg;
  EXPECT_NE(msg.find(url()), std::string::npos) << msg;
}

TEST_F(OpenAiCompletionsTest, AHungServerIsTriedTwiceNotFiveTimes) {
  // Timeouts have their own, smaller retry budget: a server that does not
  // answer costs two timeouts, while connection errors and 5xx keep theirs.
  FakeFaults f;
  f.delay_ms = 600;
  server.set_faults(f);
  auto o = options();
  o.http.total_timeout = 100ms;
  o.http.backoff_initial = 1ms;
  o.http.max_retries = 4;
  OpenAiCompletionsModel m(o);
  const std::string msg = error_of(m, {{kPrompt, kUtterance}});
  EXPECT_NE(msg.find("timed out after 2 attempts"), std::string::npos) << msg;
  // The client gave up on its second request after 100 ms; a slow server
  // (e.g. under a sanitizer) may only count it later, so wait for the count.
  const auto deadline = std::chrono::steady_clock::now() + 5s;
  while (server.completion_requests() < 2 && std::chrono::steady_clock::now() < deadline)
    std::this_thread::sleep_for(10ms);
  EXPECT_EQ(server.completion_requests(), 2);
}

TEST_F(OpenAiCompletionsTest, EveryMalformedReplyNamesTheField) {
  const std::vector<MalformedCase> cases = {
      {FakeReply::MalformedJson, 0, "body is not valid JSON"},
      {FakeReply::CutJson, 0, "body is not valid JSON"},
      {FakeReply::MissingChoices, 0, "choices missing"},
      {FakeReply::WrongChoiceCount, 0, "choices has 2 entries, expected 3"},
      {FakeReply::MissingLogprobs, 2, "choices[2].logprobs missing"},
      {FakeReply::MissingTokenLogprobs, 2, "choices[2].logprobs.token_logprobs missing"},
      {FakeReply::MissingTextOffset, 1, "choices[1].logprobs.text_offset missing"},
      {FakeReply::NullTokenLogprob, 0, "choices[0].logprobs.token_logprobs["},
      {FakeReply::NoEcho, 0, "does not seem to echo"},
  };
  std::vector<ScoreRequest> batch = {{kPrompt, " A.\n"}, {kPrompt, " B.\n"}, {kPrompt, " C.\n"}};
  for (const auto& c : cases) {
    FakeFaults f;
    f.reply = c.reply;
    f.damaged_choice = c.damaged;
    server.set_faults(f);
    OpenAiCompletionsModel m(options());
    const std::string msg = error_of(m, batch);
    EXPECT_NE(msg.find("reply from " + url() + ": "), std::string::npos) << msg;
    EXPECT_NE(msg.find(c.expected), std::string::npos) << "wanted '" << c.expected << "' in: " << msg;
  }
}

TEST_F(OpenAiCompletionsTest, TruncatedTransferFailsAfterRetries) {
  FakeFaults f;
  f.reply = FakeReply::ShortBody;
  server.set_faults(f);
  auto o = options();
  o.http.max_retries = 1;
  OpenAiCompletionsModel m(o);
  const std::string msg = error_of(m, {{kPrompt, kUtterance}});
  EXPECT_NE(msg.find(url()), std::string::npos) << msg;
  EXPECT_NE(msg.find("2 attempts"), std::string::npos) << msg;
  EXPECT_NE(msg.find("curl error 18"), std::string::npos) << msg;  // CURLE_PARTIAL_FILE
  EXPECT_EQ(server.completion_requests(), 2);
}

TEST_F(OpenAiCompletionsTest, UnreachableServerErrorsClearly) {
  // A port bound but never listened on: connecting is refused, and holding
  // the socket keeps other tests' servers (run in parallel) off that port.
  int fd = ::socket(AF_INET, SOCK_STREAM, 0);
  ASSERT_GE(fd, 0);
  sockaddr_in addr{};
  addr.sin_family = AF_INET;
  addr.sin_addr.s_addr = htonl(INADDR_LOOPBACK);
  ASSERT_EQ(::bind(fd, reinterpret_cast<sockaddr*>(&addr), sizeof addr), 0);
  socklen_t len = sizeof addr;
  ASSERT_EQ(::getsockname(fd, reinterpret_cast<sockaddr*>(&addr), &len), 0);
  const std::string base = "http://127.0.0.1:" + std::to_string(ntohs(addr.sin_port)) + "/v1";

  auto o = options();
  o.base_url = base;
  o.http.max_retries = 1;
  OpenAiCompletionsModel m(o);
  const std::string msg = error_of(m, {{kPrompt, kUtterance}});
  ::close(fd);
  EXPECT_NE(msg.find("POST " + base + "/completions failed after 2 attempts"), std::string::npos) << msg;
  EXPECT_NE(msg.find("curl error 7"), std::string::npos) << msg;  // CURLE_COULDNT_CONNECT
}

TEST_F(OpenAiCompletionsTest, AuthorizationHeaderIffKeySet) {
  auto o = options();
  o.api_key = "sk-test-123";
  OpenAiCompletionsModel with_key(o);
  with_key.score({{kPrompt, kUtterance}});
  o.api_key = "";
  OpenAiCompletionsModel without_key(o);
  without_key.score({{kPrompt, kUtterance}});
  const auto headers = server.authorization_headers();
  ASSERT_EQ(headers.size(), 2u);
  ASSERT_TRUE(headers[0].has_value());
  EXPECT_EQ(*headers[0], "Bearer sk-test-123");
  EXPECT_FALSE(headers[1].has_value());
}

TEST_F(OpenAiCompletionsTest, ReadsUrlModelAndKeyFromEnvironment) {
  EnvGuard env;
  env.set("CLIPS_LM_BASE_URL", (server.base_url() + "/").c_str());
  env.set("CLIPS_LM_MODEL", "env-model");
  env.set("OPENAI_API_KEY", "sk-env");
  OpenAiCompletionsOptions o;
  o.http.total_timeout = 500ms;
  OpenAiCompletionsModel m(o);
  EXPECT_EQ(m.endpoint(), url());
  EXPECT_EQ(m.name(), "openai:env-model");
  m.score({{kPrompt, kUtterance}});
  EXPECT_EQ(server.last_completion_body()["model"], "env-model");
  EXPECT_EQ(server.authorization_headers().back(), std::optional<std::string>("Bearer sk-env"));

  env.set("CLIPS_LM_BASE_URL", nullptr);
  env.set("CLIPS_LM_MODEL", nullptr);
  OpenAiCompletionsModel defaults{OpenAiCompletionsOptions{}};
  EXPECT_EQ(defaults.endpoint(), "https://api.openai.com/v1/completions");
  EXPECT_EQ(defaults.name(), "openai:davinci-002");
}

TEST(OpenAiSliceTest, CountsTokensFromThePromptLengthOn) {
  // "Output:" | " Hi" "!" "\n" | generated " ok"
  json lp = {{"tokens", {"Output", ":", " Hi", "!", "\n", " ok"}},
             {"token_logprobs", {nullptr, -1.0, -2.0, -3.0, -4.0, -100.0}},
             {"text_offset", {0, 6, 7, 10, 11, 12}}};
  EXPECT_DOUBLE_EQ(slice(lp, "Output:", " Hi!\n"), -9.0);
}

TEST(OpenAiSliceTest, IncludesATokenStraddlingTheBoundary) {
  // The server merged ": H" into one token that starts inside the prompt.
  json lp = {{"tokens", {"Output", ": H", "i", "\n"}},
             {"token_logprobs", {nullptr, -1.5, -2.0, -4.0}},
             {"text_offset", {0, 6, 9, 10}}};
  EXPECT_DOUBLE_EQ(slice(lp, "Output:", " Hi\n"), -7.5);
}

TEST(OpenAiSliceTest, DiscountsALeadingSpecialToken) {
  // Old vLLM: "<s>" echoed with offsets that include its text.
  json lp = {{"tokens", {"<s>", "Output", ":", " Hi", "\n"}},
             {"token_logprobs", {nullptr, -0.5, -1.0, -2.0, -4.0}},
             {"text_offset", {0, 3, 9, 10, 13}}};
  EXPECT_DOUBLE_EQ(slice(lp, "Output:", " Hi\n"), -6.0);
}

TEST(OpenAiSliceTest, OffsetsCountCharactersNotBytes) {
  json lp = {{"tokens", {"Caf\xc3\xa9", ":", " d\xc3\xa9j\xc3\xa0", "\n"}},
             {"token_logprobs", {nullptr, -1.0, -2.0, -4.0}},
             {"text_offset", {0, 4, 5, 10}}};
  EXPECT_DOUBLE_EQ(slice(lp, "Caf\xc3\xa9:", " d\xc3\xa9j\xc3\xa0\n"), -6.0);
}

TEST(OpenAiSliceTest, RejectsNullsAndBrokenOffsets) {
  json null_inside = {{"token_logprobs", {nullptr, -1.0, nullptr, -4.0}}, {"text_offset", {0, 6, 7, 10}}};
  EXPECT_NE(slice_error(null_inside, "Output:", " Hi\n").find("choices[0].logprobs.token_logprobs[2] is null"),
            std::string::npos);
  json empty_prompt = {{"token_logprobs", {nullptr, -1.0}}, {"text_offset", {0, 3}}};
  EXPECT_NE(slice_error(empty_prompt, "", " Hi\n").find("token_logprobs[0] is null"), std::string::npos);
  json decreasing = {{"token_logprobs", {nullptr, -1.0, -2.0}}, {"text_offset", {0, 7, 6}}};
  EXPECT_NE(slice_error(decreasing, "Output:", " Hi\n").find("text_offset[2] decreases"), std::string::npos);
  json mismatch = {{"token_logprobs", {nullptr, -1.0, -2.0}}, {"text_offset", {0, 7}}};
  EXPECT_NE(slice_error(mismatch, "Output:", " Hi\n").find("text_offset has 2 entries"), std::string::npos);
  json not_number = {{"token_logprobs", {nullptr, -1.0, "x"}}, {"text_offset", {0, 6, 7}}};
  EXPECT_NE(slice_error(not_number, "Output:", " Hi\n").find("token_logprobs[2] is not a number"),
            std::string::npos);
}

TEST(OpenAiSliceTest, RejectsPositiveLogProbabilitiesAndEchoesCutShort) {
  json positive = {{"tokens", {"Output", ":", " Hi", "\n"}},
                   {"token_logprobs", {nullptr, -1.0, 40.0, -4.0}},
                   {"text_offset", {0, 6, 7, 10}}};
  EXPECT_NE(slice_error(positive, "Output:", " Hi\n").find("token_logprobs[2] is 40.0, but a log-probability"),
            std::string::npos);
  // float rounding of a certain token is not an error
  json rounded = {{"tokens", {"Output", ":", " Hi", "\n"}},
                  {"token_logprobs", {nullptr, -1.0, 1e-7, -4.0}},
                  {"text_offset", {0, 6, 7, 10}}};
  EXPECT_NEAR(slice(rounded, "Output:", " Hi\n"), -4.0, 1e-6);
  // the echo stops after " Hi": the "\n" of the continuation is missing
  json short_echo = {{"tokens", {"Output", ":", " Hi"}},
                     {"token_logprobs", {nullptr, -1.0, -0.5}},
                     {"text_offset", {0, 6, 7}}};
  EXPECT_NE(slice_error(short_echo, "Output:", " Hi\n").find("echoed tokens end at character 10, before the end"),
            std::string::npos);
}

}  // namespace openai_completions_test

}  // namespace clips::lm
