// The utterance encoder: any bytes (invalid UTF-8 included) -> tokens, and the
// embedded language model's scoring of them as the continuation of a fixed
// prompt (its model is trained once, before the first input).
#include <cmath>

#include "fuzz/fuzz_target.hpp"
#include "lm/embedded_model.hpp"
#include "lm/utterance_tokens.hpp"

namespace {

// Longer utterances only repeat what shorter ones exercise, and scoring time
// grows with their length.
constexpr size_t kMaxScoredBytes = 512;

const std::string kPrompt =
    "Input: (pickup you key1)\nOutput: Get the key over there.\n"
    "Input: (handover you me key1) where (iscolor key1 red)\nOutput:";

clips::lm::EmbeddedLanguageModel& model() {
  // The trained model is cached on disk as for any other run (keyed by this
  // executable), so only the first run of a build trains it.
  static clips::lm::EmbeddedLanguageModel m;
  return m;
}

}  // namespace

#ifdef CLIPS_LIBFUZZER
// Train the prompt's model before the first input, so it does not count against -timeout.
extern "C" int LLVMFuzzerInitialize(int*, char***) {
  (void)model().score_one(kPrompt, " Hello.\n");
  return 0;
}
#endif

CLIPS_FUZZ_TARGET(utterance) {
  using namespace clips::lm;
  const std::string text = clips::fuzz::as_text(data, size);
  for (const std::string& token : tokenize_utterance(text)) {
    if (token.empty()) __builtin_trap();
    (void)is_punctuation_token(token);
    (void)is_clause_end(token);
  }
  if (size > kMaxScoredBytes) return 0;
  try {
    const double full = model().score_one(kPrompt, " " + text + "\n");
    const double prefix = model().score_one(kPrompt, " " + text);
    // Log-probabilities: never positive, never NaN.
    if (std::isnan(full) || std::isnan(prefix) || full > 1e-9 || prefix > 1e-9) __builtin_trap();
  } catch (const LmError&) {
  }
  return 0;
}
