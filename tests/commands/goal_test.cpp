// Commands as goal formulas (spec 9.9, VH spec 7.4).
#include <gtest/gtest.h>

#include "paper_languages.hpp"
#include "commands/fixtures.hpp"
#include "commands/enumerate.hpp"

namespace clips::commands {
namespace {

using testing::salient_of;

const char* kColours = "(iscolor key1 blue) (iscolor key2 red) (iscolor key3 blue) (iscolor door1 red)";

Command dkg_command(const std::string& plan) {
  const auto config = doors_keys_gems_language();
  return lift_command(salient_of(plan, kColours, config), config, testing::dkg_type_of);
}

TEST(GoalFormula, HandOverBlueKeyIsExistential) {
  const Command cmd = dkg_command("(handover robot human key1)");
  EXPECT_EQ(cmd.display_form(), "(handover you me ?key1) where (iscolor ?key1 blue)");
  EXPECT_EQ(cmd.to_goal_formula(doors_keys_gems_language()),
            "(exists (?key1 - key) (and (has human ?key1) (pickedup-by robot ?key1) (iscolor ?key1 blue)))");
}

TEST(GoalFormula, ChainKeepsRepeatedPredicates) {
  const Command cmd = dkg_command("(pickup robot key2) (handover robot human key2)");
  EXPECT_EQ(cmd.to_goal_formula(doors_keys_gems_language()),
            "(exists (?key1 - key) (and (has robot ?key1) (has human ?key1) (pickedup-by robot ?key1)"
            " (iscolor ?key1 red) (iscolor ?key1 red)))");
}

TEST(GoalFormula, VariablesArePairwiseDistinct) {
  const Command cmd = dkg_command("(unlock robot key2 door1) (pickup robot key3)");
  EXPECT_EQ(cmd.to_goal_formula(doors_keys_gems_language()),
            "(exists (?key1 - key ?door1 - door ?key2 - key) (and (unlocked-by robot ?door1)"
            " (unlocked-with ?key1 ?door1) (has robot ?key2) (not (= ?key1 ?door1)) (not (= ?key1 ?key2))"
            " (not (= ?door1 ?key2)) (iscolor ?door1 red) (iscolor ?key2 blue)))");
}

TEST(GoalFormula, SpeakerActionsMapBackToTheSpeaker) {
  Command cmd = dkg_command("(handover robot human key1)");
  cmd.actions = testing::terms("(pickup me ?key1)");
  EXPECT_EQ(cmd.to_goal_formula(doors_keys_gems_language()),
            "(exists (?key1 - key) (and (has human ?key1) (iscolor ?key1 blue)))");
}

TEST(GoalFormula, GroundCommandIsAConjunction) {
  Command cmd;
  cmd.actions = testing::terms("(pickup you key1) (unlock you key2 door1)");
  EXPECT_EQ(cmd.to_goal_formula(doors_keys_gems_language()),
            "(and (has robot key1) (unlocked-by robot door1) (unlocked-with key2 door1))");
}

TEST(GoalFormula, VirtualHomeNamesObjectsAfterVariables) {
  const auto config = virtual_home_language();
  const auto salient = salient_of(
      "(grab helper plate3 cabinet2) (grab helper plate4 cabinet2) (grab helper cutleryfork2 table1)",
      "(itemtype plate3 plate) (itemtype plate4 plate) (itemtype cutleryfork2 cutleryfork)", config);
  const Command cmd = lift_command(salient, config, testing::vh_type_of);
  // Quirk: "two plates and a fork" means plate1, plate2 and cutleryfork1 whatever was grabbed.
  EXPECT_EQ(cmd.to_goal_formula(config),
            "(and (placed plate1 table1) (placed plate2 table1) (placed cutleryfork1 table1))");
}

// A focal object that is a place keeps its name ("unlock the greenhouse" asks
// for that one), while the key and the place stood at stay lifted.
TEST(GoalFormula, AFocalPlaceIsNamed) {
  LanguageConfig config;
  config.speaker = "human";
  config.listener = "robot";
  config.print_agents_and_focal_only = true;
  config.salient_actions = {SalientActionRule{"unlock", 1, 3, 0, true}};
  config.goal_atoms["unlock"] = {"(not (locked $3))"};
  const auto type_of = [](const std::string& object) { return object == "key1" ? "key" : "place"; };
  const auto salient = salient_of("(unlock robot key1 greenhouse patio)", "", config);
  const Command named = lift_command(salient, config, type_of);
  EXPECT_EQ(named.display_form(), "(unlock you ?key1 greenhouse ?place1)");
  EXPECT_EQ(named.llm_form(), "(unlock you greenhouse)");
  EXPECT_EQ(named.to_goal_formula(config), "(and (not (locked greenhouse)))");
  config.salient_actions[0].focal_is_place = false;
  const Command lifted = lift_command(salient, config, type_of);
  EXPECT_EQ(lifted.llm_form(), "(unlock you place1)");
  // Any place: the key and the place stood at name no goal atom, so they are not quantified.
  EXPECT_EQ(lifted.to_goal_formula(config), "(exists (?place1 - place) (and (not (locked ?place1))))");
}

// A put's destination cell (where the agent stands) is in the command but in
// no goal atom: quantifying it would multiply a grid's expansion by its cells.
TEST(GoalFormula, OnlyMentionedVariablesAreQuantified) {
  LanguageConfig config;
  config.speaker = "human";
  config.listener = "robot";
  config.print_agents_and_focal_only = true;
  config.qualifier = "iscolour";
  config.salient_actions = {SalientActionRule{"put", 1, 2, 0, false}};
  config.goal_atoms["put"] = {"(on $2 $3)"};
  const auto type_of = [](const std::string& object) -> std::string {
    return object.rfind("can", 0) == 0 ? "can" : object.rfind("shelf", 0) == 0 ? "shelf" : "cell";
  };
  const auto salient = salient_of("(put robot can2 shelf3 c4-5) (put robot can1 shelf1 c1-1)",
                                  "(iscolour can2 red) (iscolour can1 blue)", config);
  const Command cmd = lift_command(salient, config, type_of);
  EXPECT_EQ(cmd.display_form(), "(put you ?can1 ?shelf1 ?cell1) (put you ?can2 ?shelf2 ?cell2) where "
                                "(iscolour ?can1 red) (iscolour ?can2 blue)");
  EXPECT_EQ(cmd.to_goal_formula(config),
            "(exists (?can1 - can ?shelf1 - shelf ?can2 - can ?shelf2 - shelf) (and (on ?can1 ?shelf1)"
            " (on ?can2 ?shelf2) (not (= ?can1 ?shelf1)) (not (= ?can1 ?can2)) (not (= ?can1 ?shelf2))"
            " (not (= ?shelf1 ?can2)) (not (= ?shelf1 ?shelf2)) (not (= ?can2 ?shelf2))"
            " (iscolour ?can1 red) (iscolour ?can2 blue)))");
}

TEST(GoalFormula, UnknownActionIsAnError) {
  Command cmd;
  cmd.actions = testing::terms("(open you ?door1)");
  EXPECT_THROW(cmd.to_goal_formula(doors_keys_gems_language()), std::invalid_argument);
}

}  // namespace
}  // namespace clips::commands
