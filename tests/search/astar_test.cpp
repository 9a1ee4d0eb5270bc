// A*, uniform-cost search and RTAA*: optimality against exhaustive search,
// heuristic properties, budgets and determinism.
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "data/dataset.hpp"
#include "domains/registry.hpp"
#include "heuristics/basic.hpp"
#include "search/rtaa.hpp"
#include "test_paths.hpp"

using namespace clips;

namespace {

std::shared_ptr<model::Specification> spec_for(const data::Dataset& ds, const std::string& problem, int gem, int costs) {
  return std::make_shared<model::Specification>(ds.task(problem), "(has human gem" + std::to_string(gem) + ")",
                                                model::dkg_profile(costs));
}

// Exact cost-to-go by Dijkstra backwards is awkward with conditional
// successors, so use forward uniform-cost search from the state itself.
double true_cost(const model::Specification& spec, const pddl::State& s, size_t budget = 1u << 20) {
  heuristics::BlindHeuristic blind;
  search::SearchOptions o;
  o.max_nodes = budget;
  auto r = search::plan(spec, blind, s, o);
  if (r.status == search::SearchStatus::Success) return r.cost;
  if (r.status == search::SearchStatus::Failure) return model::kInf;
  return std::nan("");
}

}  // namespace

TEST(AStar, HMaxMatchesUniformCostSearchOnExampleProblems) {
  auto ds = data::Dataset::load(paths::examples_dir() + "/doors-keys-gems");
  for (const char* p : {"e1", "e2"})
    for (int g = 1; g <= 4; ++g)
      for (int c = 1; c <= 4; ++c) {
        auto spec = spec_for(ds, p, g, c);
        heuristics::HMaxHeuristic h;
        auto r = search::plan(*spec, h, spec->task().initial_state());
        double ucs = true_cost(*spec, spec->task().initial_state());
        ASSERT_FALSE(std::isnan(ucs));
        if (ucs == model::kInf) {
          EXPECT_EQ(r.status, search::SearchStatus::Failure);
          continue;
        }
        ASSERT_EQ(r.status, search::SearchStatus::Success) << p << " gem" << g << " C" << c;
        EXPECT_NEAR(r.cost, ucs, 1e-9) << p << " gem" << g << " C" << c;
        // The plan is valid and reaches the goal at the reported cost.
        auto sim = pddl::simulate(spec->task(), spec->task().initial_state(), r.plan);
        EXPECT_TRUE(spec->is_goal(sim.states.back()));
        double c2 = 0;
        for (auto a : r.plan) c2 += spec->cost(a);
        EXPECT_NEAR(c2, r.cost, 1e-9);
      }
}

TEST(AStar, DefaultHeuristicMatchesUniformCostSearchOnTheDataset) {
  if (!paths::have_shared_dataset()) GTEST_SKIP() << "shared dataset not present";
  auto ds = data::Dataset::load(paths::dkg_dataset());
  std::set<std::string> problems;
  for (auto& p : ds.plans()) problems.insert(p.problem_id);
  int compared = 0, skipped = 0;
  for (auto& p : problems)
    for (int g = 1; g <= 4; ++g)
      for (int c = 1; c <= 4; ++c) {
        auto spec = spec_for(ds, p, g, c);
        auto h = domains::make_heuristic(domains::default_admissible_heuristic(ds.kind()), spec->task(), ds.kind());
        double ucs = true_cost(*spec, spec->task().initial_state(), 1u << 15);
        if (std::isnan(ucs)) {
          ++skipped;
          continue;
        }
        ++compared;
        auto r = search::plan(*spec, *h, spec->task().initial_state());
        if (ucs == model::kInf) {
          EXPECT_EQ(r.status, search::SearchStatus::Failure);
        } else {
          ASSERT_EQ(r.status, search::SearchStatus::Success) << p << " gem" << g << " C" << c;
          EXPECT_NEAR(r.cost, ucs, 1e-9) << p << " gem" << g << " C" << c;
        }
      }
  std::cout << "compared " << compared << " tasks with uniform-cost search; " << skipped
            << " exceeded the UCS budget\n";
  EXPECT_GT(compared, 0);
}

TEST(HMax, AdmissibleAndConsistentOnRandomWalks) {
  auto ds = data::Dataset::load(paths::examples_dir() + "/doors-keys-gems");
  std::mt19937 rng(7);
  for (int c : {1, 4}) {
    auto spec = spec_for(ds, "e1", 3, c);
    heuristics::HMaxHeuristic h;
    h.prepare(*spec, spec->task().initial_state());
    pddl::State s = spec->task().initial_state();
    for (int step = 0; step < 60; ++step) {
      auto acts = spec->task().applicable_actions(s);
      ASSERT_FALSE(acts.empty());
      double hs = h.estimate(s.data());
      for (auto a : acts) {
        auto t = spec->task().apply(s, a);
        EXPECT_LE(hs, spec->cost(a) + h.estimate(t.data()) + 1e-9) << "consistency";
      }
      if (step % 10 == 0) {
        double truth = true_cost(*spec, s);
        if (!std::isnan(truth)) {
          EXPECT_LE(hs, truth + 1e-9) << "admissibility";
        }
      }
      s = spec->task().apply(s, acts[rng() % acts.size()]);
    }
  }
}

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
  model::Specification spec(task, "(has robot gem1)", model::dkg_profile(1));
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

TEST(Rtaa, PathReuseMakesLaterRefinementsCheaper) {
  auto ds = data::Dataset::load(paths::examples_dir() + "/doors-keys-gems");
  auto spec = spec_for(ds, "e2", 2, 3);
  auto h = std::make_shared<heuristics::HMaxHeuristic>();
  search::Policy pol(spec, h);
  pddl::State s = spec->task().initial_state();
  auto first = pol.refine(s, search::SearchOptions{});
  auto a = pol.best_action(s);
  ASSERT_TRUE(a);
  pddl::State next = spec->task().apply(s, *a);
  auto reused = pol.refine(next, search::SearchOptions{});
  search::Policy fresh(spec, h);
  auto from_scratch = fresh.refine(next, search::SearchOptions{});
  EXPECT_GT(first.expanded, 0u);
  EXPECT_GT(pol.tree_size(), 0u);
  // Searches stop at states on the stored goal path and start from learned values.
  EXPECT_LT(reused.expanded, from_scratch.expanded);
  EXPECT_NEAR(pol.value(next), fresh.value(next), 1e-9);
  // The rollout follows the stored path to the goal.
  auto plan = pol.rollout(next, 200);
  auto sim = pddl::simulate(spec->task(), next, plan);
  EXPECT_TRUE(spec->is_goal(sim.states.back()));
}

namespace {

// h_max that counts its estimate() calls and declares whether its estimates
// may depend on the root of prepare().
struct CountingHMax : heuristics::HMaxHeuristic {
  bool root_dependent = false;
  size_t calls = 0;
  double estimate(const uint64_t* s) override {
    ++calls;
    return heuristics::HMaxHeuristic::estimate(s);
  }
  using heuristics::HMaxHeuristic::estimate;
  bool estimates_depend_on_root() const override { return root_dependent; }
};

}  // namespace

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
