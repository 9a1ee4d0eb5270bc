// The OpenAI-compatible /v1/completions reply parser, on a batch of two
// (prompt, continuation) requests, one of them with non-ASCII text (offsets
// count code points).
#include <cmath>

#include "fuzz/fuzz_target.hpp"
#include "lm/openai_model.hpp"

CLIPS_FUZZ_TARGET(completions) {
  using namespace clips::lm;
  static const ScoreRequest a{"Input: (pickup you key1)\nOutput:", " Get the key.\n"};
  static const ScoreRequest b{"Entrée: clé\nSortie:", " Donne-moi la clé rouge, s'il te plaît.\n"};
  static const std::vector<const ScoreRequest*> chunk = {&a, &b};
  try {
    for (double s : detail::parse_completions_reply(clips::fuzz::as_text(data, size), chunk, 0.5, "<reply>: "))
      if (std::isnan(s)) __builtin_trap();
  } catch (const LmError&) {
  }
  return 0;
}
