// Merging commands across two utterances (VH spec 7.3).
#include <gtest/gtest.h>

#include "paper_languages.hpp"
#include "commands/fixtures.hpp"
#include "commands/enumerate.hpp"
#include "commands/utterance_merge.hpp"

namespace clips::commands {
namespace {

Command vh_command(const std::string& grabs) {
  const auto config = virtual_home_language();
  return lift_command(testing::salient_of(grabs,
                                          "(itemtype plate1 plate) (itemtype cutleryfork1 cutleryfork)"
                                          " (itemtype bowl1 bowl)",
                                          config),
                      config, testing::vh_type_of);
}

TEST(MergeCommands, UnionOfActionsPredicatesAndVariables) {
  const Command plate = vh_command("(grab helper plate1 cabinet2)");
  const Command plate_and_fork = vh_command("(grab helper plate1 cabinet2) (grab helper cutleryfork1 cabinet4)");
  const Command fork = vh_command("(grab helper cutleryfork1 cabinet4)");
  const Command merged = merge_commands(plate, fork);
  EXPECT_EQ(to_pddl(merged.actions), "(grab you ?Plate1 ?Fixture1) (grab you ?Cutleryfork1 ?Fixture1)");
  EXPECT_EQ(merged.llm_form(), "(grab you plate1) (grab you cutleryfork1)");
  EXPECT_EQ(merged.variables,
            (std::vector<Variable>{{"Plate1", "item"}, {"Fixture1", "fixture"}, {"Cutleryfork1", "item"}}));
  EXPECT_EQ(merge_commands(plate_and_fork, plate), plate_and_fork);  // nothing new
}

TEST(CombineRankings, ProbablePrefixThenAllPairs) {
  const Command a = vh_command("(grab helper plate1 cabinet2)");
  const Command b = vh_command("(grab helper bowl1 cabinet1)");
  const Command c = vh_command("(grab helper cutleryfork1 cabinet4)");
  const std::vector<RankedCommand> first = {{a, 0.7, -1.0}, {b, 0.295, -2.0}, {c, 0.005, -9.0}};
  const auto kept = probable_prefix(first);
  ASSERT_EQ(kept.size(), 2u);  // 0.7 + 0.295 >= 0.99

  const std::vector<RankedCommand> second = {{c, 0.995, -0.5}, {a, 0.005, -7.0}};
  const auto combined = combine_utterance_rankings(kept, second);
  ASSERT_EQ(combined.size(), 2u);
  EXPECT_EQ(combined[0].command.llm_form(), "(grab you plate1) (grab you cutleryfork1)");
  EXPECT_DOUBLE_EQ(combined[0].probability, 0.7 * 0.995);
  EXPECT_DOUBLE_EQ(combined[0].score, -1.5);
  EXPECT_EQ(combined[1].command.llm_form(), "(grab you bowl1) (grab you cutleryfork1)");
  EXPECT_DOUBLE_EQ(combined[1].score, -2.5);
}

TEST(CombineRankings, SortsBySummedScore) {
  const Command a = vh_command("(grab helper plate1 cabinet2)");
  const Command b = vh_command("(grab helper bowl1 cabinet1)");
  const std::vector<RankedCommand> kept = {{a, 0.6, -1.0}, {b, 0.4, -1.2}};
  const std::vector<RankedCommand> next = {{b, 0.5, -3.0}, {a, 0.5, -1.0}};
  const auto combined = combine_utterance_rankings(kept, next);
  ASSERT_EQ(combined.size(), 4u);
  EXPECT_DOUBLE_EQ(combined[0].score, -2.0);  // a + a
  EXPECT_EQ(combined[0].command.llm_form(), "(grab you plate1)");
  EXPECT_DOUBLE_EQ(combined[1].score, -2.2);  // b + a
  EXPECT_DOUBLE_EQ(combined[3].score, -4.2);
}

}  // namespace
}  // namespace clips::commands
