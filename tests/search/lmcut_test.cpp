#include "search/lmcut_test.hpp"

// Without turns or dead preconditions: the classic LM-cut. Marking b and c
// (1 each) and reaching them (2 each) are four disjoint landmarks: h = h* = 6,
// where h_max sees only the dearest chain (5).
TEST(LmCut, ExactOnAHandCheckedChain) {
  auto task = task_of(kChainDomain, kChainProblem);
  model::Specification spec(task, "(and (visited b) (visited c))", model::task_costs_profile());
  const pddl::State s0 = task->initial_state();
  EXPECT_DOUBLE_EQ(lmcut(spec, s0), 6);
  EXPECT_DOUBLE_EQ(optimal_cost(spec, s0), 6);
  heuristics::HMaxHeuristic hmax;
  hmax.prepare(spec, s0);
  EXPECT_DOUBLE_EQ(hmax.estimate(s0.data()), 5);
}

// The turn bound on the workshop (unit costs, problem 1: both agents at the
// bench, plank1 on the rack). With the robot frozen it may only wait, so each
// of the human's steps but the last is followed by a wait: h* = 3 for
// fetching plank1 on the human's turn (move, wait, pickup) and 4 on the
// robot's (wait first). LM-cut finds both exactly; without the turn bound it
// sees the human's 2 steps only.
TEST(LmCut, TurnBoundIsExactWithAFrozenAssistant) {
  auto ds = data::Dataset::load(workshop_dir());
  auto task = ds.task("1");
  model::Specification spec(task, "(holding human plank1)", model::unit_profile());
  const pddl::State human_turn = model::freeze(*task, task->initial_state(), "robot");
  EXPECT_DOUBLE_EQ(optimal_cost(spec, human_turn), 3);
  EXPECT_DOUBLE_EQ(lmcut(spec, human_turn), 3);
  EXPECT_DOUBLE_EQ(lmcut(spec, human_turn, /*turns=*/false), 2);
  const pddl::State robot_turn = task->apply(task->initial_state(), *task->find_action("(wait human)"));
  const pddl::State frozen = model::freeze(*task, robot_turn, "robot");
  EXPECT_DOUBLE_EQ(optimal_cost(spec, frozen), 4);
  EXPECT_DOUBLE_EQ(lmcut(spec, frozen), 4);
  // At the rack on the human's turn: one pickup.
  const pddl::State at_rack = model::freeze(
      *task, task->apply(task->initial_state(), *task->find_action("(move human bench rack)")), "robot");
  const pddl::State back = task->apply(at_rack, *task->find_action("(wait robot)"));
  EXPECT_DOUBLE_EQ(lmcut(spec, back), 1);
  EXPECT_DOUBLE_EQ(optimal_cost(spec, back), 1);
}

// A goal no reachable state satisfies (one plank in two hands) is a dead end
// from the start: h^2 finds the two atoms mutex, so A* fails at once instead
// of exhausting its budget.
TEST(LmCut, MutexGoalsAreDeadEnds) {
  auto ds = data::Dataset::load(workshop_dir());
  auto task = ds.task("1");
  const auto table = heuristics::MutexTable::of(task);
  const int hp = task->atom("holding", {"human", "plank1"}).bit, rp = task->atom("holding", {"robot", "plank1"}).bit;
  const int hh = task->atom("holding", {"human", "hammer1"}).bit;
  ASSERT_GE(hp, 0);
  ASSERT_GE(rp, 0);
  EXPECT_TRUE(table->mutex(hp, rp));
  EXPECT_FALSE(table->mutex(hp, hh));
  model::Specification spec(task, "(and (holding human plank1) (holding robot plank1))", model::unit_profile());
  EXPECT_EQ(lmcut(spec, task->initial_state()), model::kInf);
  heuristics::LmCutHeuristic h;
  auto r = search::plan(spec, h, task->initial_state());
  EXPECT_EQ(r.status, search::SearchStatus::Failure);
  EXPECT_LE(r.expanded, 1u);
  // Either plank in the human's hand is fine.
  model::Specification either(task, "(or (and (holding human plank1) (holding robot plank1)) (holding human plank2))",
                              model::unit_profile());
  EXPECT_LT(lmcut(either, task->initial_state()), model::kInf);
}

// A door whose key is lost for good: with negative preconditions as atoms of
// their own, LM-cut sees the unlock the door needs (3 = h*) and the dead end
// once the key is gone (inf); without, it sees neither (1 and 1).
TEST(LmCut, NegativePreconditionsFindTheLockedDoor) {
  auto task = clips::testing::vault_task();
  model::Specification spec(task, "(inside)", model::unit_profile());
  const pddl::State s0 = task->initial_state();
  heuristics::LmCutHeuristic with, without(/*turns=*/true, /*negations=*/false);
  EXPECT_EQ(without.name(), "lmcut-noneg");
  with.prepare(spec, s0);
  without.prepare(spec, s0);
  EXPECT_DOUBLE_EQ(with.estimate(s0.data()), 3);
  EXPECT_DOUBLE_EQ(optimal_cost(spec, s0), 3);
  EXPECT_DOUBLE_EQ(without.estimate(s0.data()), 1);
  const pddl::State lost = clips::testing::after(*task, s0, {"(take)", "(lose)"});
  EXPECT_EQ(with.estimate(lost.data()), model::kInf);
  EXPECT_EQ(optimal_cost(spec, lost), model::kInf);
  EXPECT_DOUBLE_EQ(without.estimate(lost.data()), 1);
}
