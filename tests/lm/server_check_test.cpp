// The start-up scoring check (OpenAiCompletionsModel::check_scoring) against
// loopback fakes of llama.cpp (old and new /v1, native), Ollama and vLLM:
// each gets one line saying whether and how the server scores a given text,
// permanent refusals are not retried, and what the check learns (a single
// prompt, max_tokens=1, prompt_logprobs) is what scoring then uses.
#include <gtest/gtest.h>

#include <chrono>
#include <string>

#include "lm/openai_model.hpp"
#include "lm/fake_llm_servers.hpp"

namespace clips::lm {
namespace {

using fake::FakeLlmServer;
using fake::LlmFlavour;
using namespace std::chrono_literals;

bool has(const std::string& text, const std::string& part) { return text.find(part) != std::string::npos; }

OpenAiCompletionsOptions options(const FakeLlmServer& server) {
  OpenAiCompletionsOptions o;
  o.base_url = server.base_url();
  o.model = "local";
  o.api_key = "";
  o.prompt_logprobs = std::nullopt;
  o.http.connect_timeout = 500ms;
  o.http.total_timeout = 2000ms;
  o.http.max_retries = 3;
  o.http.backoff_initial = 300ms;
  return o;
}

// Every "cannot" line ends by naming the servers that can.
void expect_names_what_works(const std::string& line) {
  EXPECT_TRUE(has(line, "cannot score a given text")) << line;
  EXPECT_TRUE(has(line, "vLLM")) << line;
  EXPECT_TRUE(has(line, "echo the prompt with logprobs")) << line;
  EXPECT_EQ(line.find('\n'), std::string::npos) << line;
}

class EnvGuard {
 public:
  EnvGuard() { unsetenv("CLIPS_LM_PROMPT_LOGPROBS"); }
};

TEST(ServerCheck, OldLlamaCppRefusesEchoOnceAndIsNotRetried) {
  EnvGuard env;
  FakeLlmServer server(LlmFlavour::LlamaCppOld);
  OpenAiCompletionsModel m(options(server));
  const auto t0 = std::chrono::steady_clock::now();
  const ScoringCheck check = m.check_scoring();
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  EXPECT_FALSE(check.can_score);
  expect_names_what_works(check.line);
  EXPECT_TRUE(has(check.line, "refuses echo (HTTP 500 \"Only no echo is supported\"), as llama.cpp's server does"))
      << check.line;
  // Echo once (the 500 names a missing feature: no retry), then prompt_logprobs once.
  const auto requests = server.requests();
  ASSERT_EQ(requests.size(), 2u);
  EXPECT_EQ(requests[0]["echo"], true);
  EXPECT_TRUE(requests[1].contains("prompt_logprobs"));
  EXPECT_LT(seconds, 0.3);  // no backoff waited
  EXPECT_FALSE(m.using_prompt_logprobs());  // left as it was
}

TEST(ServerCheck, OldLlamaCppScoringFailsAtOnceToo) {
  EnvGuard env;
  FakeLlmServer server(LlmFlavour::LlamaCppOld);
  OpenAiCompletionsModel m(options(server));
  try {
    m.score({{"Input: x\nOutput:", " hi\n"}});
    FAIL() << "scored";
  } catch (const LmError& e) {
    EXPECT_TRUE(has(e.what(), "HTTP 500: Only no echo is supported")) << e.what();
  }
  EXPECT_EQ(server.requests().size(), 1u);
}

TEST(ServerCheck, NewLlamaCppIgnoresEcho) {
  EnvGuard env;
  FakeLlmServer server(LlmFlavour::LlamaCppNew);
  OpenAiCompletionsModel m(options(server));
  const ScoringCheck check = m.check_scoring();
  EXPECT_FALSE(check.can_score);
  expect_names_what_works(check.line);
  EXPECT_TRUE(has(check.line, "it ignores echo")) << check.line;
  EXPECT_TRUE(has(check.line, "text_offset missing")) << check.line;
  EXPECT_TRUE(has(check.line, "as llama.cpp's server does")) << check.line;
}

TEST(ServerCheck, LlamaCppNativeEndpointIsNamed) {
  EnvGuard env;
  FakeLlmServer server(LlmFlavour::LlamaCppNative);
  OpenAiCompletionsModel m(options(server));
  const ScoringCheck check = m.check_scoring();
  EXPECT_FALSE(check.can_score);
  expect_names_what_works(check.line);
  EXPECT_TRUE(has(check.line, "llama.cpp's native completion endpoint")) << check.line;
}

TEST(ServerCheck, OllamaGetsOnePromptThenIsFoundToIgnoreEcho) {
  EnvGuard env;
  FakeLlmServer server(LlmFlavour::Ollama);
  OpenAiCompletionsModel m(options(server));
  const ScoringCheck check = m.check_scoring();
  EXPECT_FALSE(check.can_score);
  expect_names_what_works(check.line);
  EXPECT_TRUE(has(check.line, "it ignores echo")) << check.line;
  EXPECT_TRUE(has(check.line, "as Ollama does")) << check.line;
  EXPECT_TRUE(m.single_prompt());
  const auto requests = server.requests();
  ASSERT_GE(requests.size(), 2u);
  EXPECT_TRUE(requests[0]["prompt"].is_array());  // refused: "cannot unmarshal array"
  EXPECT_TRUE(requests[1]["prompt"].is_string());
}

TEST(ServerCheck, VllmScoresWithEchoAfterTheMaxTokensFallback) {
  EnvGuard env;
  FakeLlmServer server(LlmFlavour::Vllm);
  OpenAiCompletionsModel m(options(server));
  const ScoringCheck check = m.check_scoring();
  EXPECT_TRUE(check.can_score) << check.line;
  EXPECT_TRUE(has(check.line, "scores given text with echo + logprobs, max_tokens=1")) << check.line;
  EXPECT_TRUE(m.using_max_tokens_fallback());
  const std::string prompt = "Input: (handover you me key1)\nOutput:";
  const std::string utterance = " Can you pass me the red key?\n";
  const auto scores = m.score({{prompt, utterance}});
  EXPECT_NEAR(scores[0], FakeLlmServer::continuation_logprob(prompt, utterance), 1e-12);
}

TEST(ServerCheck, VllmWithPromptLogprobsChosen) {
  EnvGuard env;
  FakeLlmServer server(LlmFlavour::Vllm);
  auto o = options(server);
  o.prompt_logprobs = true;
  OpenAiCompletionsModel m(o);
  const ScoringCheck check = m.check_scoring();
  EXPECT_TRUE(check.can_score) << check.line;
  EXPECT_TRUE(has(check.line, "scores given text with vLLM's prompt_logprobs")) << check.line;
  const std::string prompt = "Input: (pickup you key2)\nOutput:";
  const std::string utterance = " Get the blue key.\n";
  EXPECT_NEAR(m.score({{prompt, utterance}})[0], FakeLlmServer::continuation_logprob(prompt, utterance), 1e-12);
  EXPECT_FALSE(server.requests().back().contains("echo"));
}

TEST(ServerCheck, SinglePromptModeSendsStringsOneAtATime) {
  EnvGuard env;
  FakeLlmServer server(LlmFlavour::Vllm);
  auto o = options(server);
  o.single_prompt = true;
  OpenAiCompletionsModel m(o);
  const std::string prompt = "Input: (pickup you key2)\nOutput:";
  const auto scores = m.score({{prompt, " Get it.\n"}, {prompt, " The key.\n"}, {prompt, " Get it.\n"}});
  EXPECT_NEAR(scores[1], FakeLlmServer::continuation_logprob(prompt, " The key.\n"), 1e-12);
  EXPECT_DOUBLE_EQ(scores[0], scores[2]);
  std::size_t scoring = 0;
  for (const auto& r : server.requests()) {
    EXPECT_TRUE(r["prompt"].is_string()) << r.dump();
    if (r.value("max_tokens", 0) == 1) ++scoring;
  }
  EXPECT_EQ(scoring, 2u);  // two distinct pairs, one request each
}

TEST(ServerCheck, BatchSizeSetsPromptsPerRequest) {
  EnvGuard env;
  FakeLlmServer server(LlmFlavour::Vllm);
  auto o = options(server);
  o.batch_size = 2;
  o.try_max_tokens_zero = false;
  OpenAiCompletionsModel m(o);
  std::vector<ScoreRequest> batch;
  for (int i = 0; i < 5; ++i) batch.push_back({"Input: x\nOutput:", " word" + std::to_string(i) + "\n"});
  m.score(batch);
  const auto requests = server.requests();
  ASSERT_EQ(requests.size(), 3u);
  EXPECT_EQ(requests[0]["prompt"].size(), 2u);
  EXPECT_EQ(requests[2]["prompt"].size(), 1u);
}

TEST(ServerCheck, OpenAiBaseUrlIsHonoured) {
  EnvGuard env;
  FakeLlmServer server(LlmFlavour::Vllm);
  unsetenv("CLIPS_LM_BASE_URL");
  setenv("OPENAI_BASE_URL", server.base_url().c_str(), 1);
  OpenAiCompletionsOptions o;
  o.api_key = "";
  OpenAiCompletionsModel m(o);
  unsetenv("OPENAI_BASE_URL");
  EXPECT_EQ(m.endpoint(), server.base_url() + "/completions");
  EXPECT_TRUE(m.check_scoring().can_score);
}

}  // namespace
}  // namespace clips::lm
