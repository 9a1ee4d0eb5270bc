#pragma once
// Tokenisation of utterances for the embedded language model.
//
// The embedded model defines its probability distribution over *token
// sequences*, not over raw character strings. A token is either
//   * a word: a maximal run of ASCII letters/digits, lower-cased, with English
//     contractions expanded ("I'll" -> "i will", "can't" -> "can not",
//     "I'm" -> "i am", "'s" -> "s") and common chat spellings read as the
//     words they stand for ("u" -> "you", "pls" -> "please", "gimme" ->
//     "give me"), or
//   * one of the four punctuation tokens "," "." "?" "!" (";" and ":" are read
//     as ","; every other character, including the leading space, hyphens and
//     quotes, is a separator and carries no probability).
// The trailing "\n" of a continuation is the end-of-utterance event, not a token.
// Two surface strings with the same token sequence get the same score.
//
// Clauses: the sequence is cut after punctuation tokens and after the
// conjunctions listed in is_clause_end(); each clause of an utterance gets its
// own latent speech-act type in the model (request to the listener vs. a
// statement about the speaker's own plan). Cutting *after* the boundary token
// keeps the model a left-to-right generative process (the cut depends only on
// already generated tokens), so it stays properly normalised.
#include <string>
#include <string_view>
#include <vector>

namespace clips::lm {

// Split text into tokens as described above.
std::vector<std::string> tokenize_utterance(std::string_view text);

bool is_punctuation_token(std::string_view token);
// True if a clause ends after this token.
bool is_clause_end(std::string_view token);

}  // namespace clips::lm
