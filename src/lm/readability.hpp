#pragma once
// How much of an utterance the language model can read, measured the same way
// for every backend: the share of its word tokens (utterance_tokens.hpp) that
// are English words the embedded model's lexicon knows (WordNet, closed-class
// words, chat spellings the tokenizer expands, numbers). Inference uses it to
// weigh an utterance's evidence: text in another language, random letters or
// punctuation alone say little about the speaker's goal, whatever scores a
// model gives them (docs/decisions.md, "Unreadable utterances").
#include <cstddef>
#include <string_view>

namespace clips::lm {

struct UtteranceReading {
  std::size_t words = 0;     // word tokens (punctuation not counted)
  std::size_t examined = 0;  // words looked up (at most kMaxExamined, spread evenly)
  std::size_t known = 0;     // of those, readable ones
  // known / examined; 0 for an utterance without words (punctuation only).
  double share() const { return examined == 0 ? 0.0 : static_cast<double>(known) / static_cast<double>(examined); }
  static constexpr std::size_t kMaxExamined = 256;
};

UtteranceReading read_utterance(std::string_view text);

}  // namespace clips::lm
