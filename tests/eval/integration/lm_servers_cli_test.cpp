// The start-up check on the command line: against fakes of the LLM servers
// people run (llama.cpp old and new, its native endpoint, Ollama, vLLM),
// `clips listen --lm openai` says in one line on stderr whether and how the
// server scores a given text, as docs/cli.md lists; a server that cannot
// score stops the command at once with exit status 6 and no retries.
#include <gtest/gtest.h>

#include <chrono>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "eval/support.hpp"
#include "lm/fake_llm_servers.hpp"

namespace clips::eval {
namespace {

using lm::fake::FakeLlmServer;
using lm::fake::LlmFlavour;
using testing::contains;

struct Outcome {
  int status;
  std::string out;
  double seconds;
  std::vector<std::string> lines;  // the lines that start with "clips: "
};

Outcome listen_with(const FakeLlmServer& server, const std::string& extra = "") {
  const auto t0 = std::chrono::steady_clock::now();
  const auto r = testing::run("CLIPS_LM_CACHE_DIR=off OPENAI_API_KEY= CLIPS_LM_PROMPT_LOGPROBS= timeout 120 " +
                              testing::clips_binary() + " listen --dataset " + testing::examples_dkg() +
                              " --plan e1.1.keys --lm openai --lm-model local --lm-base-url " + server.base_url() +
                              " --lm-timeout 5 " + extra);
  Outcome o{r.status, r.out, std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count(), {}};
  std::istringstream in(r.out);
  for (std::string line; std::getline(in, line);)
    if (line.rfind("clips: ", 0) == 0) o.lines.push_back(line);
  return o;
}

void expect_cannot(const Outcome& o, const std::string& why) {
  EXPECT_EQ(o.status, 6) << o.out;
  ASSERT_EQ(o.lines.size(), 1u) << o.out;  // one line, and only that
  EXPECT_TRUE(contains(o.lines[0], "clips: error: language model ")) << o.lines[0];
  EXPECT_TRUE(contains(o.lines[0], "cannot score a given text: " + why)) << o.lines[0];
  EXPECT_TRUE(contains(o.lines[0], "vLLM gives them")) << o.lines[0];
  EXPECT_LT(o.seconds, 20) << "retried a permanent refusal?";
}

TEST(LmServersCli, OldLlamaCpp) {
  FakeLlmServer server(LlmFlavour::LlamaCppOld);
  expect_cannot(listen_with(server),
                "it refuses echo (HTTP 500 \"Only no echo is supported\"), as llama.cpp's server does");
  EXPECT_EQ(server.requests().size(), 2u);  // echo once, prompt_logprobs once: no retries
}

TEST(LmServersCli, NewLlamaCpp) {
  FakeLlmServer server(LlmFlavour::LlamaCppNew);
  expect_cannot(listen_with(server), "it ignores echo");
}

TEST(LmServersCli, LlamaCppNativeEndpoint) {
  FakeLlmServer server(LlmFlavour::LlamaCppNative);
  expect_cannot(listen_with(server), "the reply has no choices but llama.cpp's own fields");
}

TEST(LmServersCli, Ollama) {
  FakeLlmServer server(LlmFlavour::Ollama);
  const Outcome o = listen_with(server);
  expect_cannot(o, "it ignores echo");
  EXPECT_TRUE(contains(o.lines[0], "as Ollama does")) << o.lines[0];
}

TEST(LmServersCli, VllmScores) {
  FakeLlmServer server(LlmFlavour::Vllm);
  const Outcome o = listen_with(server);
  EXPECT_EQ(o.status, 0) << o.out;
  ASSERT_GE(o.lines.size(), 1u) << o.out;
  EXPECT_EQ(o.lines[0], "clips: language model " + server.base_url() +
                            "/completions (model local) scores given text with echo + logprobs, max_tokens=1");
  // The listener's scoring requests follow, each as the check found works.
  const auto requests = server.requests();
  ASSERT_GT(requests.size(), 2u);
  EXPECT_EQ(requests.back()["max_tokens"], 1);
  EXPECT_EQ(requests.back()["echo"], true);
}

TEST(LmServersCli, VllmPromptLogprobsAndBatchSizeFlags) {
  FakeLlmServer server(LlmFlavour::Vllm);
  const Outcome o = listen_with(server, "--lm-prompt-logprobs --lm-batch-size 3");
  EXPECT_EQ(o.status, 0) << o.out;
  ASSERT_GE(o.lines.size(), 1u) << o.out;
  EXPECT_TRUE(contains(o.lines[0], "scores given text with vLLM's prompt_logprobs, max_tokens=1")) << o.lines[0];
  for (const auto& r : server.requests()) {
    EXPECT_FALSE(r.contains("echo")) << r.dump();
    EXPECT_LE(r["prompt"].size(), 3u);
  }
}

TEST(LmServersCli, OpenAiBaseUrlFromTheEnvironment) {
  FakeLlmServer server(LlmFlavour::Vllm);
  testing::TempDir tmp("lm-env");
  const auto prompt = tmp.path / "prompt.txt";
  std::ofstream(prompt) << "Input: (pickup you key1)\nOutput:";
  const auto r = testing::run("CLIPS_LM_CACHE_DIR=off CLIPS_LM_BASE_URL= OPENAI_BASE_URL=" + server.base_url() +
                              " OPENAI_API_KEY=sk-test timeout 120 " + testing::clips_binary() +
                              " lm-score --lm openai --lm-model local --prompt-file " + prompt.string() +
                              " --continuation 'Get the key.'");
  EXPECT_EQ(r.status, 0) << r.out;
  EXPECT_TRUE(contains(r.out, "language model " + server.base_url() + "/completions")) << r.out;
  EXPECT_TRUE(contains(r.out, std::to_string(FakeLlmServer::continuation_logprob(
                                                 "Input: (pickup you key1)\nOutput:", " Get the key.\n"))
                                  .substr(0, 6)))
      << r.out;
}

}  // namespace
}  // namespace clips::eval
