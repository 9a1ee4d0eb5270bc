// Discrimination: for our own paraphrases (not from the dataset), the intended
// command must get the highest score among plausible candidates.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "lm/embedded_model.hpp"
#include "lm/embedded_prompts.hpp"

namespace clips::lm {
namespace {

using testing::literal_prompt;
using testing::pragmatic_prompt;
using testing::vh_prompt;

EmbeddedLanguageModel& model() {
  static EmbeddedLanguageModel m;
  return m;
}

struct Case {
  std::string utterance;
  std::vector<size_t> accepted;  // indices of candidates that count as correct
};

// Index of the best-scoring candidate.
size_t best(const std::vector<std::string>& commands, const std::string& utterance,
            std::string (*prompt)(const std::string&), std::vector<double>* scores = nullptr) {
  std::vector<ScoreRequest> batch;
  for (const std::string& c : commands) batch.push_back({prompt(c), " " + utterance + "\n"});
  auto s = model().score(batch);
  if (scores != nullptr) *scores = s;
  size_t b = 0;
  for (size_t i = 1; i < s.size(); ++i) {
    if (s[i] > s[b]) b = i;
  }
  return b;
}

double accuracy(const std::vector<std::string>& commands, const std::vector<Case>& cases,
                std::string (*prompt)(const std::string&), const char* label) {
  int right = 0;
  for (const Case& c : cases) {
    std::vector<double> s;
    const size_t b = best(commands, c.utterance, prompt, &s);
    const bool ok = std::find(c.accepted.begin(), c.accepted.end(), b) != c.accepted.end();
    right += ok ? 1 : 0;
    if (!ok) {
      std::printf("[%s] MISS \"%s\": top = %s (%.2f); wanted %s (%.2f)\n", label, c.utterance.c_str(),
                  commands[b].c_str(), s[b], commands[c.accepted[0]].c_str(), s[c.accepted[0]]);
    }
  }
  const double acc = static_cast<double>(right) / static_cast<double>(cases.size());
  std::printf("[%s] top-1 accuracy %d/%zu = %.3f\n", label, right, cases.size(), acc);
  return acc;
}

const std::vector<std::string> kDkgCommands = {
    "(handover you me key1) where (iscolor key1 red)",                                      // 0
    "(pickup you key1) where (iscolor key1 red)",                                           // 1
    "(handover you me key1) where (iscolor key1 blue)",                                     // 2
    "(unlock you key1 door1) where (iscolor door1 red)",                                    // 3
    "(handover you me key1) (handover you me key2) where (iscolor key1 red) (iscolor key2 red)",  // 4
    "(unlock you key1 door1) where (iscolor door1 blue)",                                   // 5
    "(pickup you key1) where (iscolor key1 blue)",                                          // 6
    "(handover you me key1) where (iscolor key1 yellow)",                                   // 7
    "(pickup you key1) where (iscolor key1 yellow)",                                        // 8
    "(unlock you key1 door1) where (iscolor door1 yellow)",                                 // 9
    "(unlock you key1 door1) (unlock you key2 door2) where (iscolor door1 red) (iscolor door2 red)",  // 10
    "(handover you me key1) (handover you me key2) where (iscolor key1 blue) (iscolor key2 yellow)",  // 11
    "(unlock you key1 door1) (handover you me key2) where (iscolor door1 blue) (iscolor key2 red)",   // 12
    "(pickup you key1) (pickup you key2) where (iscolor key1 yellow) (iscolor key2 yellow)",          // 13
};

const std::vector<Case> kDkgCases = {
    {"Could you grab me the red key?", {0}},
    {"Please fetch the blue key for me", {2}},
    {"Can you get the blue door?", {5}},
    {"Open the red door please", {3}},
    {"I need both red keys", {4}},
    {"Can you look for a yellow key?", {8, 7}},
    {"Find me a key for this blue door", {2, 5}},
    {"Bring me the red key.", {0}},
    {"Pick up the red key.", {1}},
    {"Could you hand over the yellow key?", {7}},
    {"Unlock the yellow door for me.", {9}},
    {"Can you open both red doors?", {10}},
    {"Pass me the blue and the yellow keys.", {11}},
    {"Open the blue door and then bring me a red key.", {12}},
    {"Go collect the two yellow keys.", {13}},
    {"I want the blue key.", {2}},
    {"Give me two red keys please.", {4}},
    {"Get the yellow door open.", {9}},
    {"Go grab the blue key.", {6}},
    {"Could you give me a key, the yellow one?", {7}},
    {"Toss the red key over here.", {0}},
    {"Can you unlock that red door?", {3}},
    {"Fetch me the blue one.", {2}},
    {"I'll get the red key, can you pick up the blue one?", {6, 2}},
    {"I'm heading to the gem, could you open the red door?", {3}},
    {"Can you pick up the yellow key while I get the red one?", {8}},
    {"Please take the red key.", {1}},
    {"Help me get through the yellow door.", {9}},
    {"Hand me both red keys and I'll do the rest.", {4}},
    {"The blue door is locked, please open it.", {5}},
};

TEST(EmbeddedDiscrimination, LiteralPromptRanksIntendedCommandFirst) {
  const double acc = accuracy(kDkgCommands, kDkgCases, literal_prompt, "mDKG literal");
  EXPECT_GE(acc, 0.85);
}

TEST(EmbeddedDiscrimination, PragmaticPromptRanksIntendedCommandFirst) {
  const double acc = accuracy(kDkgCommands, kDkgCases, pragmatic_prompt, "mDKG pragmatic");
  EXPECT_GE(acc, 0.85);
}

TEST(EmbeddedDiscrimination, BriefSentences) {
  // The sentences of the module brief against its six candidate commands.
  const std::vector<std::string> six(kDkgCommands.begin(), kDkgCommands.begin() + 6);
  EXPECT_EQ(best(six, "Could you grab me the red key?", literal_prompt), 0u);
  EXPECT_EQ(best(six, "Please fetch the blue key for me", literal_prompt), 2u);
  EXPECT_EQ(best(six, "Can you get the blue door?", literal_prompt), 5u);
  EXPECT_EQ(best(six, "Open the red door please", literal_prompt), 3u);
  EXPECT_EQ(best(six, "I need both red keys", literal_prompt), 4u);
  const size_t k = best(six, "Find me a key for this blue door", literal_prompt);
  EXPECT_TRUE(k == 2u || k == 5u) << k;
}

// An action group the utterance never mentions must cost clearly more than
// dilution: a mentioned group is required to emit a word.
TEST(EmbeddedDiscrimination, UnmentionedActionGroupIsPenalised) {
  const std::vector<std::string> commands = {
      "(handover you me ?key1) where (iscolor ?key1 red)",
      "(handover you me ?key1) (pickup you ?key2) where (iscolor ?key1 red) (iscolor ?key2 blue)",
      "(handover you me ?key1) (pickup you ?key2) where (iscolor ?key1 red) (iscolor ?key2 red)",
  };
  std::vector<double> s;
  EXPECT_EQ(best(commands, "Can you pass me the red key?", literal_prompt, &s), 0u);
  std::printf("[unmentioned group] gap blue %.2f, gap red %.2f nats\n", s[0] - s[1], s[0] - s[2]);
  // Before required mentions: 1.58 (mostly the unmentioned colour) and 0.88.
  // A red pickup shares "red key" with the hand-over, so it can be read as
  // mentioned; the gain there is small by design.
  EXPECT_GE(s[0] - s[1], 1.8);
  EXPECT_GT(s[0] - s[2], 0.5);
}

// Purpose modifiers: "a key for/to <door>" names the key; only an opening verb
// (or the door as the object of "get") asks for the unlock.
const std::vector<Case> kPurposeCases = {
    {"Could you fetch me the key to the blue door?", {2}},
    {"Grab the key for that yellow door.", {8}},
    {"I want the key for the red door over there.", {0}},
    {"Pick up a key for the blue door.", {6}},
    {"Toss me the yellow one for this door.", {7}},
    {"Could you go and collect the key to the locked yellow door?", {8}},
    {"Hand me the key that goes with the blue door.", {2}},  // relative clause: not modelled yet
    {"Use a key to open the red door.", {3}},
    {"Get a key and unlock the yellow door.", {9}},
    {"The red door needs a key, can you open it?", {3}},
    {"Could you get the blue door for me?", {5}},
    {"Open the blue door and then bring me a red key for the other door.", {12}},
};

TEST(EmbeddedDiscrimination, PurposeModifiersDoNotMentionUnlocking) {
  EXPECT_GE(accuracy(kDkgCommands, kPurposeCases, literal_prompt, "mDKG purpose literal"), 0.9);
  EXPECT_GE(accuracy(kDkgCommands, kPurposeCases, pragmatic_prompt, "mDKG purpose pragmatic"), 0.9);
}

const std::vector<std::string> kVhCommands = {
    "(grab you plate1) (grab you plate2) (grab you bowl1)",  // 0
    "(grab you plate1) (grab you plate2)",                   // 1
    "(grab you plate1) (grab you bowl1)",                    // 2
    "(grab you plate1)",                                     // 3
    "(grab you bowl1)",                                      // 4
    "(grab you cutleryfork1) (grab you cutleryknife1)",      // 5
    "(grab you cutleryfork1)",                               // 6
    "(grab you wine1) (grab you wineglass1)",                // 7
    "(grab you waterglass1) (grab you waterglass2)",         // 8
    "(grab you carrot1) (grab you onion1)",                  // 9
    "(grab you cheese1)",                                    // 10
    "(grab you wine1)",                                      // 11
    "(grab you salmon1) (grab you chefknife1)",              // 12
    "(grab you cuttingboard1)",                              // 13
    "(grab you bowl1) (grab you bowl2) (grab you bowl3)",    // 14
    "(grab you juice1) (grab you cupcake1)",                 // 15
};

const std::vector<Case> kVhCases = {
    {"Could you bring two plates and a bowl?", {0}},
    {"Get me a couple of plates.", {1}},
    {"A plate and a bowl, please.", {2}},
    {"Can you grab a plate?", {3}},
    {"We need a bowl.", {4}},
    {"Bring me a fork and a knife.", {5}},
    {"I need a fork.", {6}},
    {"Could you get the wine and a wine glass?", {7}},
    {"Two glasses, please.", {8}},
    {"Can you find the vegetables?", {9}},
    {"Get some cheese.", {10}},
    {"Bring the wine over.", {11}},
    {"I need the fish and a sharp knife.", {12}},
    {"Hand me the chopping board.", {13}},
    {"Set out three bowls.", {14}},
    {"Could you get me juice and a cupcake?", {15}},
    {"Grab the silverware.", {5}},
    {"Fetch two dinner plates.", {1}},
};

// Padding. The empty-command prompt "\n" scores the utterances of goals that
// need no help. Filler words a speaker adds to a request ("would it be
// possible", "as well") must not hand it to that prompt: the training corpus
// never had most of them, and they say nothing about any command.
struct PaddedCase {
  std::string command;
  std::string utterance;
  std::string (*prompt)(const std::string&);
};

double empty_prompt_score(const std::string& utterance) {
  return model().score({{"\n", " " + utterance + "\n"}}).at(0);
}

TEST(EmbeddedDiscrimination, PaddedRequestsBeatTheEmptyPrompt) {
  const std::vector<PaddedCase> cases = {
      {"(grab you bowl1) (grab you bowl2)", "Would it be possible for you to get some bowls?", vh_prompt},
      {"(grab you bowl1) (grab you bowl2)", "Some bowls would be lovely as well.", vh_prompt},
      {"(grab you plate1)", "Honestly it would be really great if you could fetch a plate.", vh_prompt},
      {"(grab you cheese1)", "Whenever you have a spare moment, the cheese would be nice.", vh_prompt},
      {"(unlock you key1 door1) where (iscolor door1 red)",
       "Any chance you could wander over here and open up the red door?", pragmatic_prompt},
      {"(handover you me key1) where (iscolor key1 blue)",
       "If it is not too much trouble, could you maybe hand me the blue key?", pragmatic_prompt},
      {"(handover you me key1) where (iscolor key1 yellow)",
       "It would honestly be wonderful if somebody passed the yellow key over to me.", pragmatic_prompt},
  };
  int right = 0;
  for (const PaddedCase& c : cases) {
    const double command = model().score({{c.prompt(c.command), " " + c.utterance + "\n"}}).at(0);
    const double none = empty_prompt_score(c.utterance);
    std::printf("[padded] %+.2f nats for the command: \"%s\"\n", command - none, c.utterance.c_str());
    right += command > none ? 1 : 0;
  }
  EXPECT_EQ(right, static_cast<int>(cases.size()));
}

// The same, measured per word: words appended to a request cost the command
// about what they cost the empty prompt (a few nats at most), whether or not
// the training corpus had them.
TEST(EmbeddedDiscrimination, FillerWordsCostCommandsLittleMoreThanTheEmptyPrompt) {
  const std::string command = "(grab you bowl1) (grab you bowl2)";
  const std::string base = "Can you get some bowls?";
  for (const std::string tail : {" Thanks a bunch, that would be splendid.", " Whenever suits, no rush whatsoever."}) {
    const std::string padded = base + tail;
    const double cost_command = model().score({{vh_prompt(command), " " + base + "\n"}}).at(0) -
                                model().score({{vh_prompt(command), " " + padded + "\n"}}).at(0);
    const double cost_none = empty_prompt_score(base) - empty_prompt_score(padded);
    int words = 0;
    for (char ch : tail) words += ch == ' ' ? 1 : 0;
    const double excess = (cost_command - cost_none) / words;
    std::printf("[filler] \"%s\": %.2f nats per word more under the command\n", tail.c_str(), excess);
    EXPECT_LT(excess, 3.0) << tail;
  }
}

TEST(EmbeddedDiscrimination, VirtualHomePromptRanksIntendedCommandFirst) {
  const double acc = accuracy(kVhCommands, kVhCases, vh_prompt, "VH");
  EXPECT_GE(acc, 0.85);
}

}  // namespace
}  // namespace clips::lm
