#pragma once
// The one interface every language-model backend implements: natural-log
// probabilities of a continuation given a prompt, for many pairs at once.
//
// Conventions (shared by all backends and callers):
//  * `prompt` is the full prompt text, e.g. few-shot lines ending in "Output:".
//  * `continuation` is exactly the text whose tokens are scored, including any
//    leading space and the trailing stop sequence, e.g. " Can you pass me the red key?\n".
//    The caller adds the leading space and the "\n" stop; backends add nothing.
//  * The result is log P(continuation | prompt) in nats; -infinity means impossible.
//  * Errors (unreachable server, malformed reply) throw LmError with a message
//    naming the backend, the URL or field involved.
#include <stdexcept>
#include <string>
#include <vector>

namespace clips::lm {

struct ScoreRequest {
  std::string prompt;
  std::string continuation;
};

class LmError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

class LanguageModel {
 public:
  virtual ~LanguageModel() = default;
  // A short name for reports, e.g. "embedded" or "openai:davinci-002".
  virtual std::string name() const = 0;
  // One log-probability per request, in request order.
  virtual std::vector<double> score(const std::vector<ScoreRequest>& batch) = 0;
};

}  // namespace clips::lm
