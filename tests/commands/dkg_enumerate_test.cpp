// Command enumeration and lifting in Doors, Keys & Gems (spec 7.3-7.6, 9.7).
#include <gtest/gtest.h>

#include "paper_languages.hpp"
#include "commands/fixtures.hpp"
#include "commands/enumerate.hpp"

namespace clips::commands {
namespace {

using testing::dkg_type_of;
using testing::salient_of;

std::vector<std::string> llm_forms(const std::vector<Command>& commands) {
  std::vector<std::string> out;
  for (const auto& c : commands) out.push_back(c.llm_form());
  return out;
}

const char* kColours =
    "(iscolor key1 red) (iscolor key2 blue) (iscolor key3 red) (iscolor key4 red) (iscolor key5 green)"
    " (iscolor door1 yellow) (iscolor door2 red) (iscolor gem1 green)";

TEST(DkgSalient, ExtractsAgentFocalObjectAndColour) {
  const auto config = doors_keys_gems_language();
  const auto salient = salient_of(
      "(right human) (pickup robot key2) (wait human) (handover robot human key2) (unlock robot key4 door1)"
      " (pickup human gem1) (up robot)",
      kColours, config);
  ASSERT_EQ(salient.size(), 4u);
  EXPECT_EQ(salient[0].agent, "robot");
  EXPECT_EQ(salient[0].focal, "key2");
  EXPECT_EQ(to_pddl(salient[0].predicates), "(iscolor key2 blue)");
  EXPECT_EQ(salient[1].focal, "key2");  // handover: the item
  EXPECT_EQ(salient[2].focal, "door1");  // unlock: the door, whose colour is attached (not the key's)
  EXPECT_EQ(to_pddl(salient[2].predicates), "(iscolor door1 yellow)");
  EXPECT_EQ(salient[3].agent, "human");
  EXPECT_EQ(to_pddl(salient[3].action), "(pickup human gem1)");
}

// Four robot actions: pickup key1 (red), pickup key2 (blue), handover key3
// (red), unlock key4/door1 (yellow door). 4 singletons + 6 pairs; every triple
// fails: {1,2,3} and {1,2,4} mix red and blue pickups, {1,3,4} and {2,3,4}
// have 3 action types. All 10 lift to distinct commands.
TEST(DkgEnumerate, FourRobotActionsGiveTenCommands) {
  const auto config = doors_keys_gems_language();
  const auto salient = salient_of(
      "(pickup robot key1) (pickup robot key2) (handover robot human key3) (unlock robot key4 door1)", kColours, config);
  EXPECT_EQ(select_command_subsets(salient, config).size(), 10u);
  const auto commands = enumerate_commands(salient, config, dkg_type_of);
  EXPECT_EQ(commands.size(), 10u);
  EXPECT_EQ(commands.front().llm_form(), "(pickup you key1) where (iscolor key1 red)");
  EXPECT_EQ(commands[3].llm_form(), "(unlock you key1 door1) where (iscolor door1 yellow)");
  EXPECT_EQ(commands.back().llm_form(),
            "(handover you me key1) (unlock you key2 door1) where (iscolor key1 red) (iscolor door1 yellow)");
  EXPECT_EQ(uniform_command_weights(commands.size()), std::vector<double>(10, 0.1));
}

// Same, but both pickups are of red keys: the triples {1,2,3} and {1,2,4}
// pass the colour rule (12 subsets); lifting merges pickup key1 / pickup
// key2, and the pairs {1,3}/{2,3} and {1,4}/{2,4}: 3 + 4 + 2 = 9 commands.
TEST(DkgEnumerate, SameColourTriplesAreKeptAndDuplicatesMerged) {
  const auto config = doors_keys_gems_language();
  const auto salient = salient_of(
      "(pickup robot key1) (pickup robot key3) (handover robot human key4) (unlock robot key2 door1)", kColours, config);
  const auto subsets = select_command_subsets(salient, config);
  ASSERT_EQ(subsets.size(), 12u);
  EXPECT_EQ(subsets[10], (std::vector<std::size_t>{0, 1, 2}));
  EXPECT_EQ(subsets[11], (std::vector<std::size_t>{0, 1, 3}));
  const auto commands = enumerate_commands(salient, config, dkg_type_of);
  EXPECT_EQ(llm_forms(commands),
            (std::vector<std::string>{
                "(pickup you key1) where (iscolor key1 red)",
                "(handover you me key1) where (iscolor key1 red)",
                "(unlock you key1 door1) where (iscolor door1 yellow)",
                "(pickup you key1) (pickup you key2) where (iscolor key1 red) (iscolor key2 red)",
                "(pickup you key1) (handover you me key2) where (iscolor key1 red) (iscolor key2 red)",
                "(pickup you key1) (unlock you key2 door1) where (iscolor key1 red) (iscolor door1 yellow)",
                "(handover you me key1) (unlock you key2 door1) where (iscolor key1 red) (iscolor door1 yellow)",
                "(pickup you key1) (pickup you key2) (handover you me key3) where (iscolor key1 red) "
                "(iscolor key2 red) (iscolor key3 red)",
                "(pickup you key1) (pickup you key2) (unlock you key3 door1) where (iscolor key1 red) "
                "(iscolor key2 red) (iscolor door1 yellow)",
            }));
}

TEST(DkgEnumerate, ColourRuleAppliesPerActionType) {
  const auto config = doors_keys_gems_language();
  // Two red pickups plus one blue handover: the handover group has one member, so it may differ.
  auto salient = salient_of("(pickup robot key1) (pickup robot key3) (handover robot human key2)", kColours, config);
  EXPECT_EQ(select_command_subsets(salient, config).size(), 7u);
  // Red and blue handovers plus a red pickup: the handover group mixes colours.
  salient = salient_of("(handover robot human key1) (handover robot human key2) (pickup robot key3)", kColours, config);
  EXPECT_EQ(select_command_subsets(salient, config).size(), 6u);
}

TEST(DkgEnumerate, ThreeActionTypesAreExcluded) {
  auto config = doors_keys_gems_language();
  const auto salient = salient_of(
      "(pickup robot key1) (handover robot human key3) (unlock robot key4 door2)", kColours, config);
  EXPECT_EQ(select_command_subsets(salient, config).size(), 6u);
  config.max_action_types = 3;
  EXPECT_EQ(select_command_subsets(salient, config).size(), 7u);
}

TEST(DkgEnumerate, KLimitsCommandSize) {
  auto config = doors_keys_gems_language();
  const auto salient = salient_of(
      "(unlock robot key1 door1) (unlock robot key2 door1) (unlock robot key3 door1) (unlock robot key4 door1)",
      kColours, config);
  // All unlocks of yellow doors: 4 + 6 + 4 subsets, the 4-subset is beyond K = 3.
  EXPECT_EQ(select_command_subsets(salient, config).size(), 14u);
  config.max_command_actions = 4;
  EXPECT_EQ(select_command_subsets(salient, config).size(), 15u);
}

TEST(DkgEnumerate, SpeakerActionsAreDroppedByDefault) {
  const auto config = doors_keys_gems_language();
  const auto salient = salient_of("(pickup human key5) (pickup robot key1) (pickup robot key3)", kColours, config);
  const auto commands = enumerate_commands(salient, config, dkg_type_of);
  EXPECT_EQ(llm_forms(commands), (std::vector<std::string>{
                                     "(pickup you key1) where (iscolor key1 red)",
                                     "(pickup you key1) (pickup you key2) where (iscolor key1 red) (iscolor key2 red)",
                                 }));
}

// Paper rule: only commands made of speaker actions alone are dropped.
// Subsets: {r1}, {r3}, 3 pairs, the triple (human pickup + two red robot
// pickups: 2 action types, one colour per type); lifted: {r1} = {r3} and
// {h,r1} = {h,r3}, so 4 commands.
TEST(DkgEnumerate, PaperSpeakerRuleKeepsJointCommands) {
  auto config = doors_keys_gems_language();
  config.speaker_actions = SpeakerActionRule::ExcludeSpeakerOnlyCommands;
  const auto salient = salient_of("(pickup human key5) (pickup robot key1) (pickup robot key3)", kColours, config);
  EXPECT_EQ(select_command_subsets(salient, config).size(), 6u);
  const auto commands = enumerate_commands(salient, config, dkg_type_of);
  EXPECT_EQ(llm_forms(commands),
            (std::vector<std::string>{
                "(pickup you key1) where (iscolor key1 red)",
                "(pickup me key1) (pickup you key2) where (iscolor key1 green) (iscolor key2 red)",
                "(pickup you key1) (pickup you key2) where (iscolor key1 red) (iscolor key2 red)",
                "(pickup me key1) (pickup you key2) (pickup you key3) where (iscolor key1 green) "
                "(iscolor key2 red) (iscolor key3 red)",
            }));
}

// Spec 7.5's example: a chained pick-up and hand-over of one key shares the
// variable and repeats the colour predicate (spec 13 item 15).
TEST(DkgLifting, ChainedActionsShareOneVariable) {
  const auto config = doors_keys_gems_language();
  const auto salient = salient_of("(pickup robot key4) (handover robot human key4)", kColours, config);
  const auto commands = enumerate_commands(salient, config, dkg_type_of);
  ASSERT_EQ(commands.size(), 3u);
  const Command& chain = commands[2];
  EXPECT_EQ(chain.display_form(),
            "(pickup you ?key1) (handover you me ?key1) where (iscolor ?key1 red) (iscolor ?key1 red)");
  EXPECT_EQ(chain.llm_form(), "(pickup you key1) (handover you me key1) where (iscolor key1 red) (iscolor key1 red)");
  EXPECT_EQ(chain.variables, (std::vector<Variable>{{"key1", "key"}}));
  EXPECT_EQ(chain.binding, (std::vector<Binding>{{"key1", "key4"}}));
}

TEST(DkgLifting, ChainsCanBeExcluded) {
  auto config = doors_keys_gems_language();
  config.exclude_chains = true;
  const auto salient = salient_of("(pickup robot key4) (handover robot human key4) (pickup robot key1)", kColours, config);
  // Pairs {pickup key4, handover key4} and the triple repeat key4.
  const auto subsets = select_command_subsets(salient, config);
  EXPECT_EQ(subsets.size(), 5u);
  for (const auto& s : subsets) EXPECT_NE(s, (std::vector<std::size_t>{0, 1}));
}

TEST(DkgLifting, VariablesAreNamedPerTypeInOrderOfFirstAppearance) {
  const auto config = doors_keys_gems_language();
  const auto salient = salient_of("(unlock robot key3 door2) (pickup robot key1) (pickup robot gem1)", kColours, config);
  const Command cmd = lift_command(salient, config, dkg_type_of);
  EXPECT_EQ(cmd.display_form(),
            "(unlock you ?key1 ?door1) (pickup you ?key2) (pickup you ?gem1) where (iscolor ?door1 red) "
            "(iscolor ?key2 red) (iscolor ?gem1 green)");
  EXPECT_EQ(cmd.variables,
            (std::vector<Variable>{{"key1", "key"}, {"door1", "door"}, {"key2", "key"}, {"gem1", "gem"}}));
  EXPECT_EQ(cmd.binding, (std::vector<Binding>{{"key1", "key3"}, {"door1", "door2"}, {"key2", "key1"}, {"gem1", "gem1"}}));
  EXPECT_EQ(to_pddl(substitute(cmd.actions, cmd.binding)), "(unlock you key3 door2) (pickup you key1) (pickup you gem1)");
}

TEST(DkgLifting, TwoRedKeysPickedUpSeparatelyLiftToOneCommand) {
  const auto config = doors_keys_gems_language();
  const auto salient = salient_of("(pickup robot key1) (pickup robot key3)", kColours, config);
  const auto commands = enumerate_commands(salient, config, dkg_type_of);
  ASSERT_EQ(commands.size(), 2u);
  EXPECT_EQ(commands[0].display_form(), "(pickup you ?key1) where (iscolor ?key1 red)");
  EXPECT_EQ(commands[0].binding, (std::vector<Binding>{{"key1", "key1"}}));  // first occurrence kept
}

TEST(DkgLifting, EmptyRolloutGivesNoCommand) {
  const auto config = doors_keys_gems_language();
  EXPECT_TRUE(enumerate_commands({}, config, dkg_type_of).empty());
  const auto salient = salient_of("(pickup human key1) (up robot)", kColours, config);
  EXPECT_TRUE(enumerate_commands(salient, config, dkg_type_of).empty());
}

// Literal listener candidates: pickups and hand-overs of key1 (red) and key2
// (blue), and the same-colour unlock key1/door2. 5 singletons and 10 pairs;
// every triple mixes colours within a type or uses 3 types.
TEST(DkgLiteral, CandidateActionsGoThroughTheSameEnumeration) {
  const auto config = doors_keys_gems_language();
  const auto candidates = testing::terms(
      "(pickup robot key1) (pickup robot key2) (handover robot human key1) (handover robot human key2)"
      " (unlock robot key1 door2)");
  const auto commands = enumerate_literal_candidates(
      candidates, config, qualifier_lookup_from_facts(testing::terms(kColours), config), dkg_type_of);
  ASSERT_EQ(commands.size(), 15u);
  EXPECT_EQ(commands[6].llm_form(),
            "(pickup you key1) (handover you me key1) where (iscolor key1 red) (iscolor key1 red)");
  EXPECT_EQ(commands[8].llm_form(),
            "(pickup you key1) (unlock you key1 door1) where (iscolor key1 red) (iscolor door1 red)");
  for (const auto& c : commands) EXPECT_LE(c.actions.size(), 2u);
}

}  // namespace
}  // namespace clips::commands
