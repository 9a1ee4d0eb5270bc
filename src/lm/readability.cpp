#include "lm/readability.hpp"

#include <algorithm>
#include <string>
#include <vector>

#include "lm/utterance_tokens.hpp"
#include "lm/wordnet_lexicon.hpp"

namespace clips::lm {

UtteranceReading read_utterance(std::string_view text) {
  UtteranceReading r;
  std::vector<std::string> words;
  for (auto& t : tokenize_utterance(text))
    if (!is_punctuation_token(t)) words.push_back(std::move(t));
  r.words = words.size();
  if (words.empty()) return r;
  // A very long utterance is judged on an even sample of its words: the
  // share is what matters, and each look-up goes through WordNet.
  const std::size_t n = std::min(words.size(), UtteranceReading::kMaxExamined);
  auto& lexicon = WordNetLexicon::instance();
  for (std::size_t i = 0; i < n; ++i) {
    const std::string& w = words[i * words.size() / n];
    const bool number = std::all_of(w.begin(), w.end(), [](char c) { return c >= '0' && c <= '9'; });
    // One-letter tokens other than "a"/"i" are fragments (e.g. of a word cut
    // by a non-ASCII letter), not words, although WordNet lists most letters.
    const bool fragment = w.size() == 1 && w != "a" && w != "i" && !number;
    if (!fragment && (number || is_function_word(w) || lexicon.knows(w))) ++r.known;
  }
  r.examined = n;
  return r;
}

}  // namespace clips::lm
