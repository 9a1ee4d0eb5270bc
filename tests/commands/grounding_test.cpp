// Naive groundings and focal objects (spec 9.11).
#include <gtest/gtest.h>

#include "paper_languages.hpp"
#include "commands/fixtures.hpp"
#include "commands/grounding.hpp"

namespace clips::commands {
namespace {

using testing::terms;

const std::map<std::string, std::vector<std::string>> kObjects = {
    {"key", {"key1", "key2", "key3", "key4"}}, {"door", {"door1", "door2"}}, {"gem", {"gem1"}}};
const auto kFacts = terms(
    "(iscolor key1 red) (iscolor key2 blue) (iscolor key3 red) (iscolor key4 red)"
    " (iscolor door1 red) (iscolor door2 blue) (iscolor gem1 green)");

Command command(const std::string& actions, const std::string& predicates, std::vector<Variable> variables) {
  Command c;
  c.actions = terms(actions);
  c.predicates = terms(predicates);
  c.variables = std::move(variables);
  return c;
}

std::vector<std::string> ground_forms(const std::vector<GroundCommand>& groundings) {
  std::vector<std::string> out;
  for (const auto& g : groundings) out.push_back(to_pddl(g.actions));
  return out;
}

TEST(NaiveGroundings, OnlyObjectsSatisfyingThePredicates) {
  const auto c = command("(handover you me ?key1)", "(iscolor ?key1 red)", {{"key1", "key"}});
  const auto g = naive_groundings(c, kObjects, kFacts);
  EXPECT_EQ(ground_forms(g), (std::vector<std::string>{"(handover you me key1)", "(handover you me key3)",
                                                        "(handover you me key4)"}));
  EXPECT_EQ(to_pddl(g[1].predicates), "(iscolor key3 red)");
  EXPECT_EQ(g[1].binding, (std::vector<Binding>{{"key1", "key3"}}));
}

// Ordered pairs of distinct red keys, kept once per set of actions: 3 of 6.
TEST(NaiveGroundings, DistinctObjectsAndSetDeduplication) {
  const auto c = command("(pickup you ?key1) (pickup you ?key2)", "(iscolor ?key1 red) (iscolor ?key2 red)",
                         {{"key1", "key"}, {"key2", "key"}});
  EXPECT_EQ(ground_forms(naive_groundings(c, kObjects, kFacts)),
            (std::vector<std::string>{"(pickup you key1) (pickup you key3)", "(pickup you key1) (pickup you key4)",
                                      "(pickup you key3) (pickup you key4)"}));
}

TEST(NaiveGroundings, UnconstrainedVariablesRangeOverTheirType) {
  const auto c = command("(unlock you ?key1 ?door1)", "(iscolor ?door1 blue)", {{"key1", "key"}, {"door1", "door"}});
  const auto g = naive_groundings(c, kObjects, kFacts);
  EXPECT_EQ(ground_forms(g), (std::vector<std::string>{"(unlock you key1 door2)", "(unlock you key2 door2)",
                                                        "(unlock you key3 door2)", "(unlock you key4 door2)"}));
  EXPECT_EQ(focal_objects(g[0].actions, doors_keys_gems_language()), (std::vector<std::string>{"door2"}));
}

TEST(NaiveGroundings, ImpossibleAndGroundCommands) {
  const auto none = command("(pickup you ?gem1)", "(iscolor ?gem1 red)", {{"gem1", "gem"}});
  EXPECT_TRUE(naive_groundings(none, kObjects, kFacts).empty());
  const auto ground = command("(pickup you key2)", "", {});
  EXPECT_EQ(ground_forms(naive_groundings(ground, kObjects, kFacts)), (std::vector<std::string>{"(pickup you key2)"}));
}

TEST(FocalObjects, ChainsNameTheirObjectOnce) {
  EXPECT_EQ(focal_objects(terms("(pickup you key4) (handover you me key4) (unlock you key1 door2) (wait you)"),
                          doors_keys_gems_language()),
            (std::vector<std::string>{"key4", "door2"}));
}

TEST(FocalObjects, MatchedAgainstAPlanForTheEfficientListener) {
  const auto c = command("(unlock you ?key1 ?door1) (handover you me ?key2)", "(iscolor ?door1 red)",
                         {{"key1", "key"}, {"door1", "door"}, {"key2", "key"}});
  const auto plan = terms(
      "(right robot) (pickup robot key3) (unlock robot key3 door1) (pickup robot key1) (handover robot human key1)"
      " (pickup human key2)");
  EXPECT_EQ(match_focal_objects(c, plan, doors_keys_gems_language()), (std::vector<std::string>{"door1", "key1"}));
}

// A focal object the command names (a place, "(unlock you greenhouse)")
// counts once an action of the plan carries that action out.
TEST(FocalObjects, ANamedPlaceIsMatchedAsItself) {
  LanguageConfig config;
  config.speaker = "human";
  config.listener = "robot";
  config.salient_actions = {SalientActionRule{"unlock", 1, 3, 0, true}};
  const auto c = command("(unlock you ?key1 greenhouse ?place1)", "", {{"key1", "key"}, {"place1", "place"}});
  EXPECT_EQ(match_focal_objects(c, terms("(unlock robot key2 greenhouse patio)"), config),
            (std::vector<std::string>{"greenhouse"}));
  EXPECT_TRUE(match_focal_objects(c, terms("(unlock robot key1 shed patio)"), config).empty());
}

}  // namespace
}  // namespace clips::commands
