#include "domains/builtin/packs.hpp"
#include "language/listener_test.hpp"

namespace clips::language {
namespace listener_test {
// Problem 1: key1 red, key2 yellow; door1 red, door2 yellow, door3 yellow.
TEST_F(DkgListener, CandidatesOfProblemOne) {
  const auto& p = data_->plan("1.1.keys");
  const auto pack = domains::builtin_pack("doors-keys-gems");
  EXPECT_EQ(printed(literal_candidate_actions(*p.task, p.s_T, *pack)),
            (std::vector<std::string>{"(pickup robot key1)", "(pickup robot key2)", "(handover robot human key1)",
                                      "(handover robot human key2)", "(unlock robot key1 door1)",
                                      "(unlock robot key2 door2)", "(unlock robot key2 door3)"}));
}

// Hand count for problem 1, actions A..G as listed above (A,B pickups red/yellow,
// C,D handovers red/yellow, E unlock red, F,G unlock yellow with the same key):
//  * singles: 7, but F and G lift alike -> 6;
//  * pairs: C(7,2) = 21, of which AG, BG, CG, DG, EG lift like AF, BF, CF, DF, EF -> 16;
//    (FG stays: it reuses ?key1 for two doors);
//  * triples: at most 2 action types and one colour per repeated type; only the
//    unlock pair FG is single-coloured, so FG plus one of A, B, C, D -> 4.
TEST_F(DkgListener, CommandCountsOfProblemOne) {
  const auto& p = data_->plan("1.1.keys");
  const auto cmds = literal_commands(*p.task, p.s_T, literal_listener_setup("doors-keys-gems"));
  EXPECT_EQ(count_with_actions(cmds, 1), 6u);
  EXPECT_EQ(count_with_actions(cmds, 2), 16u);
  EXPECT_EQ(count_with_actions(cmds, 3), 4u);
  EXPECT_EQ(cmds.size(), 26u);
  EXPECT_EQ(cmds.front().display_form(), "(pickup you ?key1) where (iscolor ?key1 red)");
  EXPECT_EQ(cmds.back().display_form(),
            "(handover you me ?key1) (unlock you ?key1 ?door1) (unlock you ?key1 ?door2) where (iscolor ?key1 yellow) "
            "(iscolor ?door1 yellow) (iscolor ?door2 yellow)");  // DFG: key2 in all three
}

// Held and used keys stay candidates (static checks only): at the end of plan
// 3.1 the robot has given key4/key5 away and door3/door1 are open, yet the
// candidate list equals the one of the initial state.
TEST_F(DkgListener, CandidatesIgnoreTheDynamicState) {
  const auto& p = data_->plan("3.1.keys");
  const auto pack = domains::builtin_pack("doors-keys-gems");
  const auto end = pddl::simulate(*p.task, p.s_T, p.completed).states.back();
  const auto at_start = literal_candidate_actions(*p.task, p.task->initial_state(), *pack);
  EXPECT_EQ(literal_candidate_actions(*p.task, end, *pack), at_start);
  // 5 keys -> 5 pickups + 5 handovers; unlocks: yellow key1-door4, blue key2-door2/door5,
  // red key3/4/5 x door1/door3 -> 1 + 2 + 6 = 9.
  EXPECT_EQ(at_start.size(), 19u);
}

TEST_F(DkgListener, OneBatchLiteralOrderAndContinuation) {
  const auto& p = data_->plan("1.1.keys");
  const auto setup = literal_listener_setup("doors-keys-gems");
  ASSERT_EQ(setup.examples.size(), 12u);
  EXPECT_EQ(setup.examples.front().index, 9);
  EXPECT_EQ(setup.examples.back().index, 4);
  EXPECT_EQ(setup.temperature, 1.0);
  FakeModel lm;
  lm.by_command["(handover you me key1) where (iscolor key1 red)\nOutput:"] = -1;
  const auto result = literal_listener(*p.task, p.s_T, "Can you pass me the red key?", setup, lm);
  ASSERT_EQ(lm.calls.size(), 1u);
  ASSERT_EQ(lm.calls[0].size(), 26u);
  for (const auto& r : lm.calls[0]) EXPECT_EQ(r.continuation, " Can you pass me the red key?\n");
  const std::string& prompt = lm.calls[0][0].prompt;
  EXPECT_EQ(prompt.rfind("Input: (unlock you key1 door1) (unlock you key2 door2) where (iscolor door1 green) "
                         "(iscolor door2 yellow)\nOutput: Help me unlock the green and yellow doors.\n"
                         "Input: (unlock you key1 door1) (unlock you key2 door2) (unlock you key3 door3)\n",
                         0),
            0u);
  EXPECT_TRUE(prompt.ends_with("\nInput: (pickup you key1) where (iscolor key1 red)\nOutput:"));
  ASSERT_EQ(result.commands.size(), 26u);
  EXPECT_EQ(result.commands[0].command.display_form(), "(handover you me ?key1) where (iscolor ?key1 red)");
  // Softmax over one -1 and 25 times -10.
  const double expected = std::exp(-1.0) / (std::exp(-1.0) + 25 * std::exp(-10.0));
  EXPECT_NEAR(result.commands[0].prob, expected, 1e-12);
  double total = 0;
  for (const auto& r : result.commands) total += r.prob;
  EXPECT_NEAR(total, 1.0, 1e-12);
  for (size_t i = 1; i < result.commands.size(); ++i) EXPECT_GE(result.commands[i - 1].prob, result.commands[i].prob);
}

TEST_F(DkgListener, BlankUtteranceIsAnInputError) {
  const auto& p = data_->plan("1.1.keys");
  FakeModel lm;
  EXPECT_THROW(literal_listener(*p.task, p.s_T, " \t ", literal_listener_setup("doors-keys-gems"), lm), InputError);
  EXPECT_TRUE(lm.calls.empty());
}

TEST_F(DkgListener, CompletedPlanSatisfiesItsCommands) {
  // 3.1.keys: the robot picks up key5 and key4 (red) and hands both over; the
  // human spends key4 on door3 before key5 arrives, so no single state has
  // both keys with the human, but the plan did hand over two red keys.
  const auto& p = data_->plan("3.1.keys");
  const auto setup = literal_listener_setup("doors-keys-gems");
  const auto& config = setup.config;
  const auto cmds = literal_commands(*p.task, p.s_T, setup);
  auto find = [&](const std::string& display) {
    for (const auto& c : cmds)
      if (c.display_form() == display) return c;
    ADD_FAILURE() << "no command " << display;
    return Command{};
  };
  const Command two_red = find("(handover you me ?key1) (handover you me ?key2) where (iscolor ?key1 red) (iscolor ?key2 red)");
  EXPECT_TRUE(completed_plan_satisfies(*p.task, p.observed, p.completed, two_red, config));
  const auto states = pddl::simulate(*p.task, p.s_T, p.completed).states;
  for (const auto& s : states) EXPECT_FALSE(state_satisfies_command(*p.task, s, two_red, config));
  EXPECT_TRUE(state_satisfies_command(*p.task, achieved_facts(*p.task, states), two_red, config));
  EXPECT_FALSE(completed_plan_satisfies(*p.task, p.observed, p.completed,
                                        find("(handover you me ?key1) where (iscolor ?key1 blue)"), config));
  EXPECT_FALSE(completed_plan_satisfies(*p.task, p.observed, p.completed,
                                        find("(unlock you ?key1 ?door1) where (iscolor ?door1 red)"), config));
  EXPECT_TRUE(completed_plan_satisfies(*p.task, p.observed, p.completed,
                                       find("(pickup you ?key1) where (iscolor ?key1 red)"), config));
}

// VH plan 2.1: the actor holds plate1 at s_T, so 15 items remain placed:
// bowl1-4 in cabinet1, plate2-4 in cabinet2, forks and knives 1-4 in cabinet4.
TEST(VhListener, CandidatesCountsAndTemperature) {
  if (!testing::have_vh_dataset()) GTEST_SKIP() << "no dataset at " << paths::vh_dataset();
  testing::DatasetFixture data(paths::vh_dataset());
  const auto& p = data.plan("2.1.set_table1");
  const auto setup = literal_listener_setup("virtual-home");
  EXPECT_EQ(setup.temperature, 0.5);
  ASSERT_EQ(setup.examples.size(), 12u);
  EXPECT_EQ(setup.examples.front().index, 5);
  const auto cands = printed(literal_candidate_actions(*p.task, p.s_T, *setup.pack));
  ASSERT_EQ(cands.size(), 15u);
  EXPECT_EQ(cands.front(), "(grab helper bowl1 cabinet1)");
  EXPECT_EQ(cands[4], "(grab helper plate2 cabinet2)");
  EXPECT_EQ(cands.back(), "(grab helper cutleryknife4 cabinet4)");
  const auto cmds = literal_commands(*p.task, p.s_T, setup);
  // Singles: one per item type. Pairs: ordered type pairs in candidate order
  // (bowl<plate<fork<knife), fixture sharing implied by the types: bb, bp, bf,
  // bk, pp, pf, pk, ff, fk, kk.
  EXPECT_EQ(count_with_actions(cmds, 1), 4u);
  EXPECT_EQ(count_with_actions(cmds, 2), 10u);
  EXPECT_EQ(cmds.front().llm_form(), "(grab you bowl1)");

  FakeModel lm;
  lm.by_command["(grab you cutleryfork1) (grab you cutleryknife1)\nOutput:"] = -3;
  const auto result = literal_listener(*p.task, p.s_T, "Can you get a fork and a knife?", setup, lm);
  ASSERT_EQ(lm.calls.size(), 1u);
  EXPECT_EQ(lm.calls[0].size(), cmds.size());
  // Scores are divided by the temperature 0.5.
  EXPECT_EQ(result.commands[0].command.llm_form(), "(grab you cutleryfork1) (grab you cutleryknife1)");
  EXPECT_DOUBLE_EQ(result.commands[0].log_likelihood, -6.0);
  EXPECT_DOUBLE_EQ(result.commands.back().log_likelihood, -20.0);
}

}  // namespace listener_test

}  // namespace clips::language
