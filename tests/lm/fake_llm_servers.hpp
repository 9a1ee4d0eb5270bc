#pragma once
// Loopback stand-ins for the LLM servers people run at home, each answering
// in that server's own shape, for the start-up scoring check (tests only):
//  * LlamaCppOld: llama.cpp's /v1/completions before it ignored echo: HTTP 500
//    "Only no echo is supported" to echo, no logprobs otherwise;
//  * LlamaCppNew: llama.cpp's /v1/completions now: echo ignored, logprobs of the
//    generated tokens only, chat-style (logprobs.content), no text_offset;
//  * LlamaCppNative: llama.cpp's own /completion(s) endpoint (a base URL
//    without /v1): {"content", "completion_probabilities"}, an array of them
//    for an array of prompts, no "choices";
//  * Ollama: /v1/completions takes one prompt as a string (an array is the Go
//    error "cannot unmarshal array ..."), ignores echo and logprobs;
//  * Vllm: refuses max_tokens=0, echoes the prompt with logprobs
//    (text_offset, token_logprobs, tokens) and answers prompt_logprobs.
// Tokens: a space or a newline starts one, so the pieces spell the text.
#include <memory>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

namespace clips::lm::fake {

enum class LlmFlavour { LlamaCppOld, LlamaCppNew, LlamaCppNative, Ollama, Vllm };

class FakeLlmServer {
 public:
  explicit FakeLlmServer(LlmFlavour flavour);  // listens on 127.0.0.1 at once
  ~FakeLlmServer();
  FakeLlmServer(const FakeLlmServer&) = delete;
  FakeLlmServer& operator=(const FakeLlmServer&) = delete;

  // The base URL a user would give: ".../v1", or the bare host for LlamaCppNative.
  std::string base_url() const;
  std::vector<nlohmann::json> requests() const;  // every request body, in order

  // The fake model's log-probability of a token, and of the tokens of
  // prompt + continuation that start at or after the prompt's end.
  static double logprob_of(const std::string& token);
  static double continuation_logprob(const std::string& prompt, const std::string& continuation);

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace clips::lm::fake
