#pragma once
// The includes, helpers and fixtures of the lm tests in alignment_behaviour_test.cpp, shared by
// the files of that name in tests/lm/ and its label folders
// (docs/testing.md, "Labels").
// Score tests for behaviours of the alignment model (alignment_model.hpp) that
// the other embedded-model tests leave unpinned, and a golden-score regression
// test that holds the model's numbers fixed across refactorings.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>

#include "lm/embedded_model.hpp"
#include "lm/embedded_prompts.hpp"

namespace clips::lm {
namespace alignment_behaviour_test {

using testing::literal_prompt;
using testing::pragmatic_prompt;
using testing::vh_prompt;

// The default model, from the on-disk cache when this executable has trained
// it before (CTest points the cache into the build folder). A stale entry
// cannot hide a change: entries are keyed by the executable's file, the
// training pairs (corpus and few-shot examples), the EM iterations and the
// WordNet files, so changed code or data trains afresh.
EmbeddedLanguageModel& model() {
  static EmbeddedLanguageModel m;
  return m;
}

double score(const std::string& prompt, const std::string& continuation) {
  return model().score({{prompt, continuation}}).at(0);
}

// How many nats the command of prompt `a` explains an utterance better than
// that of prompt `b`.
double lead(const std::string& a, const std::string& b, const std::string& utterance) {
  return score(a, utterance) - score(b, utterance);
}

struct Golden {
  const char* kind;  // "L" literal, "P" pragmatic, "V" virtual-home, "E" empty prompt
  const char* command;
  const char* continuation;
  double log_prob;
};

std::string prompt_of(const Golden& g) {
  switch (g.kind[0]) {
    case 'L': return literal_prompt(g.command);
    case 'P': return pragmatic_prompt(g.command);
    case 'V': return vh_prompt(g.command);
    default: return "\n";
  }
}

// The log-scores below were recorded by running this test against the
// unsplit alignment_model.cpp (commit a126c13) with CLIPS_GOLDEN_PRINT=1, and
// re-recorded when what a later request's "it" points back to became the
// listener's (EncodedUtterance::about_request; EM moves every score) and when
// "the red one" became contradicted like "the red key", and when a clause
// addressed to the listener ("could you ...") became a request with 0.99, and
// when one announcing the speaker's own step ("I'll grab ...", "while I
// get ...") became theirs,
// with the listener's anchors scaled down there (EM moves every score a
// little), and when the numbers in names got a mention rate of their own and
// negated values stopped being copied (issue 60; a few hundredths of a nat), and
// when "it" could point back to a noun-less "one" (training version 3); they
// are not derived by hand. They cover every step of the model: length, mention
// sums, anchors, clause types, modifiers, colour binding and contradiction,
// number binding, pronoun antecedents, misspellings, unknown words, prefixes
// and the empty-command prompt. Re-record them only for an intended change of
// the model, and say so in the commit.
const std::vector<Golden> kGolden = {
    {"L", "(pickup you key1) where (iscolor key1 red)", " Could you grab the red key for me?\n", -33.185562186628026},
    {"L", "(unlock you key1 door1) where (iscolor door1 blue)", " Unlock the blue door.\n", -17.719862885802549},
    {"L", "(handover you me key1) (handover you me key2) where (iscolor key1 red) (iscolor key2 red)",
     " Bring me both red", -13.810884042119291},
    {"P", "(pickup you key1) where (iscolor key1 blue)", " I'll grab the red key, could you pick up the blue one?\n", -56.010349959884273},
    {"P", "(handover you me key1) where (iscolor key1 yellow)", " Grab the key for that yellow door.\n", -28.931569446184884},
    {"P", "(unlock you ?key1 ?door1) where (iscolor ?door1 red)",
     " This red door has me stuck; could you open it?\n", -70.69275002291721},
    {"P", "(unlock you ?key1 ?door1) where (iscolor ?door1 blue)", " Can you open the red door?\n", -30.7328475489984},
    {"P", "(handover you me key1) (pickup you key2) where (iscolor key1 red) (iscolor key2 blue)",
     " Pass me the red key pls, would it be possible?\n", -76.506403850983247},
    {"L", "(pickup you key1) where (iscolor key1 green)", " Grab the grene key zyzzyva!\n", -57.680574626186804},
    {"V", "(grab you cutleryfork1) (grab you cutleryfork2) (grab you wineglass1)", " Could you get two forks?\n", -24.967446157586171},
    {"V", "(grab you mug1) (grab you plate1)", " Get a mug and a plate.\n", -25.684876082677039},
    {"V", "(grab you chefknife1)", " The wine is in the kitchen.\n", -44.803895015712321},
    {"E", "", " Hello there.\n", -28.156391505829017},
};

}  // namespace alignment_behaviour_test
using namespace alignment_behaviour_test;
}  // namespace clips::lm
