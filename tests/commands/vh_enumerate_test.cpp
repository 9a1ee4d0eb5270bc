// Command enumeration, lifting and printing in VirtualHome (VH spec 6.2-6.7, 7.1).
#include <gtest/gtest.h>

#include "paper_languages.hpp"
#include "commands/fixtures.hpp"
#include "commands/enumerate.hpp"

namespace clips::commands {
namespace {

using testing::salient_of;
using testing::vh_type_of;

const char* kItemTypes =
    "(itemtype plate1 plate) (itemtype plate2 plate) (itemtype plate3 plate) (itemtype bowl1 bowl)"
    " (itemtype cutleryfork1 cutleryfork) (itemtype cutleryknife1 cutleryknife)";

std::vector<std::string> llm_forms(const std::vector<Command>& commands) {
  std::vector<std::string> out;
  for (const auto& c : commands) out.push_back(c.llm_form());
  return out;
}

// A rollout from plan 2.1's s_2 towards set_table1 with the actor barred from
// grabbing: the helper fetches plate1, then the fork and knife.
const char* kSetTable1Rollout =
    "(wait actor) (move helper table1 cabinet2) (wait actor) (grab helper plate1 cabinet2)"
    " (wait actor) (move helper cabinet2 cabinet4) (wait actor) (grab helper cutleryfork1 cabinet4)"
    " (wait actor) (grab helper cutleryknife1 cabinet4) (wait actor) (move helper cabinet4 table1)"
    " (wait actor) (put helper plate1 table1) (wait actor) (put helper cutleryfork1 table1)"
    " (wait actor) (put helper cutleryknife1 table1)";

TEST(VhWorkedExample, SetTable1GivesSixCommands) {
  const auto config = virtual_home_language();
  const auto salient = salient_of(kSetTable1Rollout, kItemTypes, config);
  ASSERT_EQ(salient.size(), 3u);
  EXPECT_EQ(to_pddl(salient[1].predicates), "(itemtype cutleryfork1 cutleryfork)");
  const auto commands = enumerate_commands(salient, config, vh_type_of);
  EXPECT_EQ(llm_forms(commands), (std::vector<std::string>{
                                     "(grab you plate1)",
                                     "(grab you cutleryfork1)",
                                     "(grab you cutleryknife1)",
                                     "(grab you plate1) (grab you cutleryfork1)",
                                     "(grab you plate1) (grab you cutleryknife1)",
                                     "(grab you cutleryfork1) (grab you cutleryknife1)",
                                 }));
}

TEST(VhWorkedExample, SetTable1bGivesTenCommands) {
  const auto config = virtual_home_language();
  const std::string rollout = std::string(kSetTable1Rollout) +
                              " (wait actor) (move helper table1 cabinet1) (wait actor) (grab helper bowl1 cabinet1)";
  const auto commands = enumerate_commands(salient_of(rollout, kItemTypes, config), config, vh_type_of);
  ASSERT_EQ(commands.size(), 10u);  // 4 singletons + 6 pairs; triples and the quadruple have > 2 item types
  EXPECT_EQ(commands.back().llm_form(), "(grab you cutleryknife1) (grab you bowl1)");
}

TEST(VhWorkedExample, PlateGoalsGiveOneCommandPerCount) {
  const auto config = virtual_home_language();
  const auto salient = salient_of(
      "(grab helper plate1 cabinet2) (wait actor) (grab helper plate2 cabinet2) (wait actor) (grab helper plate3 cabinet2)",
      kItemTypes, config);
  const auto commands = enumerate_commands(salient, config, vh_type_of);
  EXPECT_EQ(llm_forms(commands), (std::vector<std::string>{
                                     "(grab you plate1)",
                                     "(grab you plate1) (grab you plate2)",
                                     "(grab you plate1) (grab you plate2) (grab you plate3)",
                                 }));
}

TEST(VhEnumerate, AtMostTwoItemTypesFromThreeGrabsOn) {
  const auto config = virtual_home_language();
  // plate, plate, bowl: the triple is kept; pairs {p1,b} and {p2,b} lift alike.
  auto salient = salient_of("(grab helper plate1 cabinet2) (grab helper plate2 cabinet2) (grab helper bowl1 cabinet1)",
                            kItemTypes, config);
  EXPECT_EQ(select_command_subsets(salient, config).size(), 7u);
  EXPECT_EQ(llm_forms(enumerate_commands(salient, config, vh_type_of)),
            (std::vector<std::string>{
                "(grab you plate1)",
                "(grab you bowl1)",
                "(grab you plate1) (grab you plate2)",
                "(grab you plate1) (grab you bowl1)",
                "(grab you plate1) (grab you plate2) (grab you bowl1)",
            }));
  // plate, fork, knife, bowl: 4 + 6, no larger subset has <= 2 types.
  salient = salient_of(
      "(grab helper plate1 cabinet2) (grab helper cutleryfork1 cabinet4) (grab helper cutleryknife1 cabinet4)"
      " (grab helper bowl1 cabinet1)",
      kItemTypes, config);
  EXPECT_EQ(select_command_subsets(salient, config).size(), 10u);
}

TEST(VhEnumerate, ActorGrabsAreNeverCommanded) {
  const auto config = virtual_home_language();
  const auto salient = salient_of("(grab actor plate1 cabinet2) (grab helper bowl1 cabinet1)", kItemTypes, config);
  EXPECT_EQ(llm_forms(enumerate_commands(salient, config, vh_type_of)),
            (std::vector<std::string>{"(grab you bowl1)"}));
}

TEST(VhLifting, ItemVariablesFollowItemTypesAndFixturesAreShared) {
  const auto config = virtual_home_language();
  const auto salient = salient_of(
      "(grab helper cutleryfork1 cabinet4) (grab helper cutleryknife1 cabinet4) (grab helper plate3 cabinet2)",
      kItemTypes, config);
  const Command cmd = lift_command(salient, config, vh_type_of);
  EXPECT_EQ(to_pddl(cmd.actions),
            "(grab you ?Cutleryfork1 ?Fixture1) (grab you ?Cutleryknife1 ?Fixture1) (grab you ?Plate1 ?Fixture2)");
  EXPECT_EQ(cmd.variables, (std::vector<Variable>{{"Cutleryfork1", "item"},
                                                  {"Fixture1", "fixture"},
                                                  {"Cutleryknife1", "item"},
                                                  {"Plate1", "item"},
                                                  {"Fixture2", "fixture"}}));
  EXPECT_EQ(cmd.display_form(),
            "(grab you ?cutleryfork1 ?fixture1) (grab you ?cutleryknife1 ?fixture1) (grab you ?plate1 ?fixture2) "
            "where (itemtype ?cutleryfork1 cutleryfork) (itemtype ?cutleryknife1 cutleryknife) (itemtype ?plate1 plate)");
  // No `where`: the fixtures and the itemtype predicates are dropped.
  EXPECT_EQ(cmd.llm_form(), "(grab you cutleryfork1) (grab you cutleryknife1) (grab you plate1)");
}

// VH spec 7.1 quirk: fixtures are lifted too, so two plates from one cabinet
// and two plates from different places stay distinct yet print alike.
TEST(VhLiteral, FixtureStructureKeepsIdenticallyPrintedCommandsApart) {
  const auto config = virtual_home_language();
  const auto commands = enumerate_literal_candidates(
      testing::terms("(grab helper plate1 cabinet2) (grab helper plate2 cabinet2) (grab helper plate3 table1)"),
      config, qualifier_lookup_from_facts(testing::terms(kItemTypes), config), vh_type_of);
  EXPECT_EQ(llm_forms(commands), (std::vector<std::string>{
                                     "(grab you plate1)",
                                     "(grab you plate1) (grab you plate2)",
                                     "(grab you plate1) (grab you plate2)",
                                     "(grab you plate1) (grab you plate2) (grab you plate3)",
                                 }));
  EXPECT_EQ(to_pddl(commands[1].actions), "(grab you ?Plate1 ?Fixture1) (grab you ?Plate2 ?Fixture1)");
  EXPECT_EQ(to_pddl(commands[2].actions), "(grab you ?Plate1 ?Fixture1) (grab you ?Plate2 ?Fixture2)");
}

}  // namespace
}  // namespace clips::commands
