// The relaxation behind hff and lmcut (heuristics/relaxed.hpp) on a task with
// turns: a goal's negative literal keeps its negation atom (those atoms are
// numbered after the task's, and only turn atoms leave a goal clause), and a
// specification relaxed after others of the same task gets what a fresh one
// does (the goal- and cost-free part is shared per task).
#include <gtest/gtest.h>

#include "data/dataset.hpp"
#include "heuristics/basic.hpp"
#include "heuristics/lmcut.hpp"
#include "heuristics/relaxed.hpp"
#include "test_paths.hpp"

using namespace clips;

namespace {

heuristics::RelaxedTask::Options lmcut_options() {
  heuristics::RelaxedTask::Options o;
  o.turns = o.dead_preconditions = o.dedup_preconditions = o.normalise_goal = o.relevant_only = o.negations = true;
  return o;
}

TEST(RelaxedTask, AGoalsNegativeLiteralKeepsItsAtomWhereTurnsAreLeftOut) {
  // The warehouse: turns added by clips; (lies can1 c1-1) is deleted by a
  // pickup and negated by no precondition, so the goal brings its negation
  // atom, numbered after the task's atoms.
  auto ds = data::Dataset::load(paths::source_dir() + "/data/datasets/warehouse");
  auto task = ds.task("1");
  model::Specification spec(task, "(not (lies can1 c1-1))", model::unit_profile());
  const heuristics::RelaxedTask r = heuristics::RelaxedTask::of(spec, lmcut_options());
  ASSERT_TRUE(r.use_turns);
  ASSERT_EQ(r.goal_clauses.size(), 1u);
  ASSERT_EQ(r.goal_clauses[0].size(), 1u);
  EXPECT_GE(r.goal_clauses[0][0], r.num_state_atoms);
  EXPECT_FALSE(r.goal_trivial);
  // Someone must walk to the can and pick it up: never estimated free.
  const pddl::State s0 = task->initial_state();
  heuristics::LmCutHeuristic lmcut;
  lmcut.prepare(spec, s0);
  EXPECT_GE(lmcut.estimate(s0.data()), 2.0);
  heuristics::FFHeuristic ff;
  ff.prepare(spec, s0);
  EXPECT_GE(ff.estimate(s0.data()), 2.0);
}

TEST(RelaxedTask, ASpecificationAfterOthersOfItsTaskIsRelaxedAsAFreshOne) {
  auto ds = data::Dataset::load(paths::source_dir() + "/data/datasets/warehouse");
  auto task = ds.task("1");
  const heuristics::RelaxedTask::Options o = lmcut_options();
  model::CostProfile dear = model::unit_profile();
  dear.name = "dear-robot";
  dear.costs[{"robot", "pickup"}] = 3;
  // Relaxed first against a task of its own (nothing shared yet), then after
  // specifications with other goals and costs have been relaxed on `task`.
  auto fresh_task = ds.task("1");
  ASSERT_EQ(fresh_task, task);  // the dataset grounds a problem once
  const std::string goal = "(and (holding human can1) (on can2 shelf1))";
  const heuristics::RelaxedTask first = heuristics::RelaxedTask::of(model::Specification(task, goal, dear), o);
  for (const char* other : {"(on can1 shelf1)", "(holding robot can2)", "(not (lies can1 c1-1))"})
    (void)heuristics::RelaxedTask::of(model::Specification(task, other, model::unit_profile()), o);
  const heuristics::RelaxedTask again = heuristics::RelaxedTask::of(model::Specification(task, goal, dear), o);
  EXPECT_EQ(first.num_atoms, again.num_atoms);
  EXPECT_EQ(first.negated, again.negated);
  EXPECT_EQ(first.op_action, again.op_action);
  EXPECT_EQ(first.pre, again.pre);
  EXPECT_EQ(first.add, again.add);
  EXPECT_EQ(first.cost, again.cost);
  EXPECT_EQ(first.needed_by, again.needed_by);
  EXPECT_EQ(first.goal_clauses, again.goal_clauses);
  EXPECT_EQ(first.agent_safe_min, again.agent_safe_min);
  EXPECT_EQ(first.agent_killable, again.agent_killable);
  // The costs are the specification's own: the robot's pickups cost 3 here.
  bool dear_pickup = false;
  for (size_t op = 0; op < again.op_action.size(); ++op)
    if (again.op_action[op] >= 0 && task->action_name(again.op_action[op]).rfind("(pickup robot", 0) == 0)
      dear_pickup = dear_pickup || again.cost[op] == 3;
  EXPECT_TRUE(dear_pickup);
}

}  // namespace
