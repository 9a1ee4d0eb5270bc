#pragma once
// A loopback stand-in for an OpenAI-compatible server, for tests only:
// /v1/completions with echo + logprobs semantics and /v1/chat/completions,
// each with switchable faults. Binds 127.0.0.1 on an ephemeral port and
// serves from a background thread between start() and stop().
#include <atomic>
#include <cstddef>
#include <functional>
#include <memory>
#include <mutex>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <thread>
#include <vector>

namespace httplib {
class Server;
}

namespace clips::lm::fake {

// What the next replies look like (after any injected failures).
enum class FakeReply {
  Ok,
  MalformedJson,         // body is not JSON at all
  CutJson,               // body cut mid-JSON, Content-Length matches the cut body
  ShortBody,             // Content-Length promises more bytes than are sent
  MissingChoices,        // no "choices" field
  WrongChoiceCount,      // one choice fewer than prompts
  MissingLogprobs,       // choices[damaged].logprobs absent
  MissingTokenLogprobs,  // choices[damaged].logprobs.token_logprobs absent
  MissingTextOffset,     // choices[damaged].logprobs.text_offset absent
  NullTokenLogprob,      // last token of choices[damaged] has a null log-prob
  NoEcho,                // logprobs cover only generated tokens (echo ignored)
  NonJsonAnswer,         // chat: the assistant text is not JSON
  MissingContent,        // chat: message.content null (with a refusal)
  Endless,               // a chunked reply that never ends (until the client hangs up or stop())
  HugeNumber,            // the first token log-prob written as -1e999 (valid JSON, no double holds it)
};

struct FakeFaults {
  int delay_ms = 0;              // sleep before answering
  int fail_first = 0;            // the next N requests fail with fail_status
  int fail_status = 500;
  std::string retry_after;       // Retry-After value sent with failures; "" = none
  bool reject_max_tokens_zero = false;  // 400 like vLLM for max_tokens == 0
  bool reverse_choices = false;  // answer a batch in reverse order (with index fields)
  FakeReply reply = FakeReply::Ok;
  std::size_t damaged_choice = 0;
};

struct FakeToken {
  std::string text;
  std::size_t offset;  // in characters (code points), like OpenAI's text_offset
};

class FakeOpenAiServer {
 public:
  // Total log-prob of `continuation` after `prompt` (the text is split after
  // the last "\nOutput:"); the server spreads it evenly over the tokens.
  using Scorer = std::function<double(const std::string& prompt, const std::string& continuation)>;

  FakeOpenAiServer();
  ~FakeOpenAiServer();
  FakeOpenAiServer(const FakeOpenAiServer&) = delete;
  FakeOpenAiServer& operator=(const FakeOpenAiServer&) = delete;

  void start();  // once per instance; stop() is idempotent and runs on destruction
  void stop();
  int port() const { return port_; }
  std::string base_url() const;  // "http://127.0.0.1:<port>/v1"

  void set_faults(const FakeFaults& faults);
  void set_scorer(Scorer scorer);  // empty = the built-in unigram-ish model
  // The chat answer's content for a request body; empty = the built-in JSON
  // summary of what was asked. Faults (NonJsonAnswer, ...) still apply.
  using ChatRule = std::function<std::string(const nlohmann::json& request)>;
  void set_chat_rule(ChatRule rule);

  // Server-side bookkeeping, for assertions.
  int completion_requests() const;
  int chat_requests() const;
  std::vector<std::size_t> prompts_per_request() const;
  std::vector<std::optional<std::string>> authorization_headers() const;  // per request
  nlohmann::json last_completion_body() const;
  nlohmann::json last_chat_body() const;

  // The tokenizer and the log-probs the server would return (for expectations).
  static std::vector<FakeToken> tokenize(const std::string& text);
  static double unigram_logprob(const std::string& token);
  std::vector<double> token_logprobs(const std::string& text) const;  // [0] is NaN (null)
  static constexpr double kGeneratedLogprob = -0.5;
  static constexpr const char* kGeneratedToken = " ok";

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
  int port_ = -1;
};

}  // namespace clips::lm::fake
