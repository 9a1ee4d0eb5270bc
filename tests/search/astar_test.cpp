#include "search/astar_test.hpp"
#include "domains/builtin/packs.hpp"

TEST(AStar, BudgetExhaustionIsAStatusAndSearchIsDeterministic) {
  auto ds = data::Dataset::load(paths::examples_dir() + "/doors-keys-gems");
  auto spec = spec_for(ds, "e2", 1, 1);
  heuristics::BlindHeuristic blind;
  search::SearchOptions o;
  o.max_nodes = 50;
  auto r = search::plan(*spec, blind, spec->task().initial_state(), o);
  EXPECT_EQ(r.status, search::SearchStatus::MaxNodes);
  EXPECT_EQ(r.expanded, 50u);
  EXPECT_TRUE(r.plan.empty());
  heuristics::HMaxHeuristic h1, h2;
  auto a = search::plan(*spec, h1, spec->task().initial_state());
  auto b = search::plan(*spec, h2, spec->task().initial_state());
  EXPECT_EQ(a.plan, b.plan);
  EXPECT_EQ(a.expanded, b.expanded);
}

TEST(AStar, UnreachableGoalFailsFast) {
  auto ds = data::Dataset::load(paths::examples_dir() + "/doors-keys-gems");
  auto task = ds.task("e1");
  // The robot may never hold a gem.
  model::Specification spec(task, "(has robot gem1)", fixtures::dkg_profile(1));
  heuristics::HMaxHeuristic h;
  auto r = search::plan(spec, h, task->initial_state());
  EXPECT_EQ(r.status, search::SearchStatus::Failure);
  EXPECT_LE(r.expanded, 1u);
}

TEST(Rtaa, ValuesNeverOverestimateAndBecomeExactWithEnoughBudget) {
  auto ds = data::Dataset::load(paths::examples_dir() + "/doors-keys-gems");
  auto spec = spec_for(ds, "e1", 3, 3);
  auto h = std::make_shared<heuristics::HMaxHeuristic>();
  search::Policy pol(spec, h);
  pddl::State s = spec->task().initial_state();
  search::SearchOptions small;
  small.max_nodes = 20;
  pol.refine(s, small);
  // Every learned value is admissible (-V <= true cost-to-go), checked on the
  // successors of s, which all got values.
  for (auto a : spec->task().applicable_actions(s)) {
    auto t = spec->task().apply(s, a);
    double truth = true_cost(*spec, t);
    ASSERT_FALSE(std::isnan(truth));
    EXPECT_LE(-pol.value(t), truth + 1e-9);
  }
  // With a budget that lets every lookahead finish, V(s) is the optimal cost.
  search::Policy exact(spec, h);
  exact.refine(s, search::SearchOptions{});
  EXPECT_NEAR(-exact.value(s), true_cost(*spec, s), 1e-9);
  // Q-values: the best action's Q equals V(s); following best actions
  // reaches the goal at the optimal cost.
  auto qs = exact.q_values(s);
  double best = -model::kInf;
  for (auto& q : qs) best = std::max(best, q.q);
  EXPECT_NEAR(best, exact.value(s), 1e-9);
  double cost = 0;
  pddl::State cur = s;
  for (int i = 0; i < 100 && !spec->is_goal(cur); ++i) {
    exact.refine(cur, search::SearchOptions{});
    auto a = exact.best_action(cur);
    ASSERT_TRUE(a);
    cost += spec->cost(*a);
    cur = spec->task().apply(cur, *a);
  }
  EXPECT_TRUE(spec->is_goal(cur));
  EXPECT_NEAR(cost, true_cost(*spec, s), 1e-9);
}

TEST(Rtaa, CachedEstimatesAreReusedOnlyWhenTheHeuristicAllowsIt) {
  // Two refinements at the same state: the second may reuse the first's
  // estimates of frontier states unless the heuristic says estimates depend
  // on the root; either way the learned values are the same (h_max does not
  // depend on it).
  auto ds = data::Dataset::load(paths::examples_dir() + "/doors-keys-gems");
  auto spec = spec_for(ds, "e2", 1, 1);
  const pddl::State s0 = spec->task().initial_state();
  size_t second[2];
  double values[2];
  for (int dep = 0; dep < 2; ++dep) {
    auto h = std::make_shared<CountingHMax>();
    h->root_dependent = dep == 1;
    search::Policy pi(spec, h);
    search::SearchOptions o;
    o.max_nodes = 64;  // small searches leave frontier states behind
    pi.refine(s0, o);
    const size_t first = h->calls;
    pi.refine(s0, o);
    second[dep] = h->calls - first;
    values[dep] = pi.value(s0);
  }
  EXPECT_LT(second[0], second[1]);
  EXPECT_EQ(values[0], values[1]);
}

TEST(Rtaa, LookaheadMatchesTheSpecsRefineOnPlainAStar) {
  // Refinements along a random walk (so the pruning sets change with the
  // root), with budgets small enough to stop searches early and unlimited:
  // the learned values and Q-values equal the reference's exactly.
  auto ds = data::Dataset::load(paths::examples_dir() + "/doors-keys-gems");
  for (const char* problem : {"e1", "e2"}) {
    for (size_t budget : {size_t{16}, size_t{200}, std::numeric_limits<size_t>::max()}) {
      auto spec = spec_for(ds, problem, 1, 3);
      const pddl::Task& task = spec->task();
      search::Policy pol(spec, domains::builtin_pack("doors-keys-gems")->make_heuristic("dkg-mst", task));
      ReferenceRefine ref{spec, domains::builtin_pack("doors-keys-gems")->make_heuristic("dkg-mst", task), {}, {}};
      search::SearchOptions o;
      o.max_nodes = budget;
      std::mt19937 rng(7);
      pddl::State s = task.initial_state();
      for (int step = 0; step < 25 && !spec->is_goal(s); ++step) {
        pol.refine(s, o);
        ref.refine(s, o);
        ASSERT_EQ(pol.value(s), ref.value(s.data())) << problem << " budget " << budget << " step " << step;
        const auto acts = task.applicable_actions(s);
        for (pddl::ActionId a : acts) {
          const pddl::State c = task.apply(s, a);
          EXPECT_EQ(pol.value(c), ref.value(c.data())) << problem << " step " << step << " " << task.action_name(a);
        }
        s = task.apply(s, acts[std::uniform_int_distribution<size_t>(0, acts.size() - 1)(rng)]);
      }
      EXPECT_EQ(pol.tree_size(), ref.tree.size()) << problem << " budget " << budget;
    }
  }
}
