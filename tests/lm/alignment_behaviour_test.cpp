// Score tests for behaviours of the alignment model (alignment_model.hpp) that
// the other embedded-model tests leave unpinned, and a golden-score regression
// test that holds the model's numbers fixed across refactorings.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>

#include "language/lm/embedded_model.hpp"
#include "lm/embedded_prompts.hpp"

namespace clips::lm {
namespace {

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

// Item 4, C: the copy probability alpha is one parameter shared by all
// colours, so a colour the corpus has rarely ("orange": 21 times, against 292
// for "blue") is copied from the command as readily as a frequent one. Without the
// copy only the contradiction of item 7 tells the keys apart (3.2 and 3.4
// nats when the copy was disabled to check this test; 5.2 and 8.8 with it).
TEST(AlignmentBehaviour, RareColoursAreCopiedAsReadilyAsFrequentOnes) {
  const std::string orange = literal_prompt("(pickup you key1) where (iscolor key1 orange)");
  const std::string blue = literal_prompt("(pickup you key1) where (iscolor key1 blue)");
  const double gap_orange = lead(orange, blue, " Pick up the orange key.\n");
  const double gap_blue = lead(blue, orange, " Pick up the blue key.\n");
  std::printf("[shared copy] orange %.2f, blue %.2f nats\n", gap_orange, gap_blue);
  EXPECT_GT(gap_orange, 4.5);
  EXPECT_GT(gap_blue, 4.5);
  // Rare or frequent, the copied colour tells the keys apart (the rare one
  // even more: the shared residual table already expects "blue" anywhere).
  EXPECT_GT(gap_orange, gap_blue - 1.0);
}

// Item 4, P: a hand-over's recipient unit emits "here", "my way", ... when
// mentioned. Appending such a word to a request helps a hand-over to the
// speaker and not a pickup of the same key (the verb and noun are the same
// in both utterances, so the difference of differences is the recipient's).
TEST(AlignmentBehaviour, RecipientWordsSpeakForHandOvers) {
  const std::string hand = literal_prompt("(handover you me key1) where (iscolor key1 red)");
  const std::string pick = literal_prompt("(pickup you key1) where (iscolor key1 red)");
  const char* plain = " Bring the red key.\n";
  const char* here = " Bring the red key here.\n";
  const double gain_hand = score(hand, here) - score(hand, plain);
  const double gain_pick = score(pick, here) - score(pick, plain);
  std::printf("[recipient] \"here\" gains %.2f nats for the hand-over, %.2f for the pickup\n", gain_hand, gain_pick);
  // (4.2 nats; 0 with the recipient unit disabled.)
  EXPECT_GT(gain_hand, gain_pick + 1.0);
}

// Item 4: the noun phrase an earlier clause names, when a later request asks
// for "it", is the request's object. "I need the red key, could you get it?"
// asks the listener for the red key; it does not say that the speaker gets
// the red key while the listener gets some other key.
TEST(AlignmentBehaviour, WhatALaterItPointsBackToIsTheRequestsObject) {
  const std::string asked = pragmatic_prompt("(pickup you key1) where (iscolor key1 red)");
  const std::string split = pragmatic_prompt("(pickup me key1) (pickup you key2) where (iscolor key1 red) (iscolor key2 blue)");
  const double gap = lead(asked, split, " I need the red key, could you get it?\n");
  std::printf("[it] the request for the red key leads the split by %.2f nats\n", gap);
  // (5.7 nats; 4.2 when the first clause was read as the speaker's own.)
  EXPECT_GT(gap, 5.0);
}

// Item 7: "the red one" has no noun, but in a request it is one of the
// listener's objects, so it contradicts a command whose only object the
// listener handles is blue, as "the red key" does.
TEST(AlignmentBehaviour, TheRedOneMiscoloursARequestForTheBlueKey) {
  const std::string red = pragmatic_prompt("(pickup you key1) where (iscolor key1 red)");
  const std::string blue = pragmatic_prompt("(pickup you key1) where (iscolor key1 blue)");
  const double gap = lead(red, blue, " Could you get me the red one?\n");
  const double keyed = lead(red, blue, " Could you get me the red key?\n");
  std::printf("[one] the red one: %.2f nats, the red key: %.2f nats\n", gap, keyed);
  // (5.6 nats; 3.8 when "one" left the colour unconstrained.)
  EXPECT_GT(gap, 5.0);
  EXPECT_GT(gap, keyed - 1.0);
}

// Item 3: a clause that announces the speaker's own step ("I'll open ...")
// is theirs. Its verb cannot stand for the listener's opening, so "I'll open
// the red door. Get the blue key." asks the listener for the key, not for
// the door while the speaker fetches the key.
TEST(AlignmentBehaviour, AnAnnouncedStepIsTheSpeakersOwn) {
  const std::string mine = pragmatic_prompt(
      "(unlock me key1 door1) (pickup you key2) where (iscolor door1 red) (iscolor key2 blue)");
  const std::string yours = pragmatic_prompt(
      "(unlock you key1 door1) (pickup me key2) where (iscolor door1 red) (iscolor key2 blue)");
  const double gap = lead(mine, yours, " I'll open the red door. Get the blue key.\n");
  std::printf("[announced] the speaker's opening leads by %.2f nats\n", gap);
  // (8.7 nats; 1.9 before the announcing clause was marked.)
  EXPECT_GT(gap, 5.0);
  // Said in the present, after "while": the same.
  const double present = lead(mine, yours, " Get the blue key while I open the red door.\n");
  std::printf("[announced] in the present, by %.2f nats\n", present);
  // (7.9 nats; 0.8 with "I will" and the like alone marked.)
  EXPECT_GT(present, 3.0);
  // "I'll need ..." is not the speaker's step: it asks for the key.
  const std::string fetch = pragmatic_prompt("(pickup you key1) where (iscolor key1 red)");
  const std::string own = pragmatic_prompt("(pickup me key1) where (iscolor key1 red)");
  const double need = lead(fetch, own, " I'll need the red key.\n");
  const double get = lead(fetch, own, " I'll get the red key.\n");
  std::printf("[announced] \"I'll need\" favours the listener's pickup by %.2f nats, \"I'll get\" by %.2f\n", need, get);
  // (-0.75 and -3.41 nats; -0.66 and -0.63 before.)
  EXPECT_GT(need, get + 1.0);
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
// negated values stopped being copied (issue 60; a few hundredths of a nat); they
// are not derived by hand. They cover every step of the model: length, mention
// sums, anchors, clause types, modifiers, colour binding and contradiction,
// number binding, pronoun antecedents, misspellings, unknown words, prefixes
// and the empty-command prompt. Re-record them only for an intended change of
// the model, and say so in the commit.
const std::vector<Golden> kGolden = {
    {"L", "(pickup you key1) where (iscolor key1 red)", " Could you grab the red key for me?\n", -33.185507092441732},
    {"L", "(unlock you key1 door1) where (iscolor door1 blue)", " Unlock the blue door.\n", -17.72004908855655},
    {"L", "(handover you me key1) (handover you me key2) where (iscolor key1 red) (iscolor key2 red)",
     " Bring me both red", -13.811103028182551},
    {"P", "(pickup you key1) where (iscolor key1 blue)", " I'll grab the red key, could you pick up the blue one?\n", -55.990430253726728},
    {"P", "(handover you me key1) where (iscolor key1 yellow)", " Grab the key for that yellow door.\n", -28.933144228273903},
    {"P", "(unlock you ?key1 ?door1) where (iscolor ?door1 red)",
     " This red door has me stuck; could you open it?\n", -70.692992052953187},
    {"P", "(unlock you ?key1 ?door1) where (iscolor ?door1 blue)", " Can you open the red door?\n", -30.711838777505399},
    {"P", "(handover you me key1) (pickup you key2) where (iscolor key1 red) (iscolor key2 blue)",
     " Pass me the red key pls, would it be possible?\n", -76.507492634964223},
    {"L", "(pickup you key1) where (iscolor key1 green)", " Grab the grene key zyzzyva!\n", -57.68078607310833},
    {"V", "(grab you cutleryfork1) (grab you cutleryfork2) (grab you wineglass1)", " Could you get two forks?\n", -24.967599677277363},
    {"V", "(grab you mug1) (grab you plate1)", " Get a mug and a plate.\n", -25.685214290517948},
    {"V", "(grab you chefknife1)", " The wine is in the kitchen.\n", -44.807170168908222},
    {"E", "", " Hello there.\n", -28.156360275835297},
};

TEST(AlignmentGolden, ScoresMatchTheRecordedOnes) {
  const bool print = std::getenv("CLIPS_GOLDEN_PRINT") != nullptr;
  for (const Golden& g : kGolden) {
    const double s = score(prompt_of(g), g.continuation);
    if (print) std::printf("GOLDEN %.17g  %s | %s\n", s, g.command, g.continuation);
    EXPECT_NEAR(s, g.log_prob, 1e-9) << g.kind << " " << g.command << " /" << g.continuation;
  }
}

}  // namespace
}  // namespace clips::lm
