// A*, uniform-cost search and RTAA*: optimality against exhaustive search,
// heuristic properties, budgets and determinism.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <map>
#include <random>
#include <set>

#include "data/dataset.hpp"
#include "domains/pack.hpp"
#include "heuristics/basic.hpp"
#include "search/rtaa.hpp"
#include "test_paths.hpp"
#include "dkg_profiles.hpp"

using namespace clips;

namespace {

std::shared_ptr<model::Specification> spec_for(const data::Dataset& ds, const std::string& problem, int gem, int costs) {
  return std::make_shared<model::Specification>(ds.task(problem), "(has human gem" + std::to_string(gem) + ")",
                                                fixtures::dkg_profile(costs));
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
        auto h = ds.pack().make_heuristic(ds.pack().default_admissible_heuristic(), spec->task());
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

// h_FF: at least h_max (a relaxed plan reaches every goal atom, so it costs at
// least the dearest one), 0 at goals, and A* with it finds valid plans no
// cheaper than optimal. On the workshop (STRIPS, goals needing several
// fetches) it counts every fetch where h_max sees only the longest.
TEST(HFF, BoundsAndPlansOnTheWorkshop) {
  auto ds = data::Dataset::load(CLIPS_SOURCE_DIR "/data/datasets/workshop");
  std::mt19937 rng(11);
  int larger = 0;
  for (const char* problem : {"1", "3"}) {
    auto task = ds.task(problem);
    for (const char* product : {"table", "birdhouse", "frame"}) {
      if (!task->find_object(product)) continue;
      auto spec = std::make_shared<model::Specification>(task, std::string("(made ") + product + ")",
                                                         model::unit_profile());
      heuristics::FFHeuristic ff;
      heuristics::HMaxHeuristic hmax;
      pddl::State s = task->initial_state();
      ff.prepare(*spec, s);
      hmax.prepare(*spec, s);
      for (int step = 0; step < 12 && !spec->is_goal(s); ++step) {
        const double hf = ff.estimate(s.data()), hm = hmax.estimate(s.data());
        EXPECT_GE(hf + 1e-9, hm) << problem << " " << product << " step " << step;
        if (hf > hm + 1e-9) ++larger;
        auto acts = task->applicable_actions(s);
        ASSERT_FALSE(acts.empty());
        s = task->apply(s, acts[rng() % acts.size()]);
      }
      heuristics::HMaxHeuristic optimal;
      auto best = search::plan(*spec, optimal, task->initial_state());
      auto r = search::plan(*spec, ff, task->initial_state());
      ASSERT_EQ(r.status, search::SearchStatus::Success) << problem << " " << product;
      ASSERT_EQ(best.status, search::SearchStatus::Success) << problem << " " << product;
      auto sim = pddl::simulate(*task, task->initial_state(), r.plan);
      EXPECT_TRUE(spec->is_goal(sim.states.back()));
      EXPECT_GE(r.cost + 1e-9, best.cost);
      EXPECT_LT(r.expanded, best.expanded) << "h_FF should guide A* better than h_max here";
      EXPECT_EQ(ff.estimate(sim.states.back().data()), 0);
    }
  }
  EXPECT_GT(larger, 0) << "h_FF should see more than the dearest subgoal somewhere";
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

namespace {

// The spec's REFINE / UPDATE (clips-spec.md 5.3) written directly on the
// generic A*, with its own value table and tree: the reference the
// Policy's specialised lookahead (cached successors, entry ids) must match.
struct ReferenceRefine {
  std::shared_ptr<const model::Specification> spec;
  std::shared_ptr<heuristics::Heuristic> h;
  std::map<std::vector<uint64_t>, double> v;
  std::set<std::vector<uint64_t>> tree;

  std::vector<uint64_t> key(const uint64_t* s) const { return {s, s + spec->task().num_words()}; }
  double value(const uint64_t* s) const {
    auto it = v.find(key(s));
    return it != v.end() ? it->second : -h->estimate(s);
  }

  void refine(const pddl::State& s, const search::SearchOptions& opts_in) {
    const pddl::Task& task = spec->task();
    h->prepare(*spec, s);
    struct Learned : heuristics::Heuristic {
      ReferenceRefine* r;
      explicit Learned(ReferenceRefine* rr) : r(rr) {}
      std::string name() const override { return "reference-learned"; }
      bool admissible() const override { return false; }
      bool consistent() const override { return false; }
      void prepare(const model::Specification&, const pddl::State&) override {}
      double estimate(const uint64_t* x) override { return -r->value(x); }
      bool prunes() const override { return r->h->prunes(); }
      bool keep(pddl::ActionId a) const override { return r->h->keep(a); }
    } learned(this);
    search::SearchOptions opts = opts_in;
    opts.extra_goal = [this](const uint64_t* x) { return tree.count(key(x)) != 0; };
    double best = -model::kInf;
    for (pddl::ActionId a : task.applicable_actions(s)) {
      const pddl::State c = task.apply(s, a);
      auto known = v.find(c.words);
      if (known != v.end() && known->second == -model::kInf) continue;
      if (spec->is_goal(c)) {
        v[c.words] = 0;
      } else {
        const search::SearchResult r = search::astar(*spec, learned, c, opts);
        const search::StateRegistry& reg = *r.registry;
        if (r.status == search::SearchStatus::Failure) {
          for (int id = 0; id < reg.size(); ++id) v[key(reg.get(id))] = -model::kInf;
        } else {
          const auto& t = r.nodes[r.terminal];
          const double f_t = t.g + t.h;
          v[key(reg.get(r.terminal))] = -t.h;
          for (int id = 0; id < reg.size(); ++id)
            if (!r.nodes[id].open && id != r.terminal) v[key(reg.get(id))] = -(f_t - r.nodes[id].g);
          if (r.status == search::SearchStatus::Success)
            for (int id = r.terminal; r.nodes[id].parent >= 0; id = r.nodes[id].parent)
              tree.insert(key(reg.get(r.nodes[id].parent)));
        }
      }
      best = std::max(best, -spec->cost(a) + value(c.data()));
    }
    v[s.words] = best;
  }
};

}  // namespace

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
