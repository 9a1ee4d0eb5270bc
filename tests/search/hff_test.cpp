// h_FF: the plain form (`hff-plain`) gives exactly the values of the h_FF
// clips had before its rewrite (the reference below is that code), and the
// turn-aware default counts the turns a frozen assistant's waits take.
#include <gtest/gtest.h>

#include <queue>
#include <random>

#include "data/dataset.hpp"
#include "heuristics/basic.hpp"
#include "test_paths.hpp"
#include "vault_task.hpp"

using namespace clips;

namespace {

using model::kInf;

// The h_FF estimate as it was (heuristics/basic.cpp before the rewrite).
double reference_hff(const heuristics::Relaxation& r, const model::Specification& spec, const uint64_t* s) {
  if (spec.is_goal(s)) return 0;
  const pddl::Task& t = spec.task();
  const int na = t.num_actions(), nb = t.num_atoms();
  std::vector<double> atom_cost(nb, kInf), act_cost(na, 0);
  std::vector<int> unsat(na, 0), supporter(nb, -1);
  using QE = std::pair<double, int>;
  std::priority_queue<QE, std::vector<QE>, std::greater<QE>> q;
  for (int b = 0; b < nb; ++b)
    if (pddl::get_bit(s, b)) {
      atom_cost[b] = 0;
      q.push({0, b});
    }
  auto relax = [&](int a) {
    const double ac = act_cost[a] + r.cost[a];
    for (int e : r.add[a])
      if (ac < atom_cost[e]) {
        atom_cost[e] = ac;
        supporter[e] = a;
        q.push({ac, e});
      }
  };
  for (int a = 0; a < na; ++a) {
    unsat[a] = static_cast<int>(r.pre[a].size());
    if (unsat[a] == 0) relax(a);
  }
  while (!q.empty()) {
    auto [c, b] = q.top();
    q.pop();
    if (c > atom_cost[b]) continue;
    for (int a : r.needed_by[b]) {
      act_cost[a] += c;
      if (--unsat[a] == 0) relax(a);
    }
  }
  const std::vector<int>* best = nullptr;
  double best_cost = kInf;
  for (auto& clause : r.goal_clauses) {
    double sum = 0;
    for (int b : clause) sum += atom_cost[b];
    if (sum < best_cost) best_cost = sum, best = &clause;
  }
  if (!best || best_cost >= kInf) return kInf;
  std::vector<char> in_plan(na, 0), done(nb, 0);
  double h = 0;
  std::vector<int> open(best->begin(), best->end());
  while (!open.empty()) {
    const int b = open.back();
    open.pop_back();
    if (done[b]) continue;
    done[b] = 1;
    const int a = supporter[b];
    if (a < 0 || in_plan[a]) continue;
    in_plan[a] = 1;
    h += r.cost[a];
    for (int p : r.pre[a]) open.push_back(p);
  }
  return h;
}

}  // namespace

// Bit for bit on random walks of the workshop and the storeroom (unit costs
// and a 0.6 wait, which makes h_add's sums inexact in binary), frozen
// assistant or not: the early stop, the queue-free first pops and the flat
// arrays change nothing.
TEST(HFF, PlainFormEqualsTheReference) {
  std::mt19937 rng(3);
  model::CostProfile cheap_wait = model::unit_profile();
  cheap_wait.name = "wait-0.6";
  cheap_wait.costs[{"human", "wait"}] = 0.6;
  cheap_wait.costs[{"robot", "wait"}] = 0.6;
  int compared = 0;
  for (const std::string& dir : {paths::source_dir() + "/data/datasets/workshop",
                                paths::source_dir() + "/bench/data/storeroom"}) {
    auto ds = data::Dataset::load(dir);
    for (const char* problem : {"1", "2", "4"}) {
      auto task = ds.task(problem);
      for (const auto& profile : {model::unit_profile(), cheap_wait}) {
        for (int o = 0; o < task->num_objects(); ++o) {
          if (!task->object_is_a(o, "product")) continue;
          model::Specification spec(task, "(made " + task->object_name(o) + ")", profile);
          const heuristics::Relaxation r = heuristics::Relaxation::of(spec);
          heuristics::FFHeuristic plain(/*turns=*/false);
          plain.prepare(spec, task->initial_state());
          pddl::State s = task->initial_state();
          for (int step = 0; step < 30; ++step) {
            for (bool freeze : {false, true}) {
              const pddl::State t = freeze ? model::freeze(*task, s, "robot") : s;
              ASSERT_EQ(plain.estimate(t.data()), reference_hff(r, spec, t.data()))
                  << dir << " " << problem << " step " << step;
              ++compared;
            }
            auto acts = task->applicable_actions(s);
            if (acts.empty()) break;
            s = task->apply(s, acts[rng() % acts.size()]);
          }
        }
      }
    }
  }
  EXPECT_GE(compared, 500);
}

// With the assistant frozen, every action of the human's relaxed plan but the
// last waits for one turn of the assistant: fetching plank1 from the rack in
// workshop problem 1 (move, pickup) is 2 relaxed actions and 1 wait.
TEST(HFF, CountsTheTurnsOfAFrozenAssistant) {
  auto ds = data::Dataset::load(paths::source_dir() + "/data/datasets/workshop");
  auto task = ds.task("1");
  model::Specification spec(task, "(holding human plank1)", model::unit_profile());
  const pddl::State s = model::freeze(*task, task->initial_state(), "robot");
  heuristics::FFHeuristic turns, plain(false);
  turns.prepare(spec, s);
  plain.prepare(spec, s);
  EXPECT_DOUBLE_EQ(plain.estimate(s.data()), 2);
  EXPECT_DOUBLE_EQ(turns.estimate(s.data()), 3);
  EXPECT_EQ(turns.name(), "hff");
  EXPECT_EQ(plain.name(), "hff-plain");
}

// A negative precondition some action makes true is an atom of its own: the
// locked door costs its key and its unlocking (h = h* = 3, where ignoring the
// negation gives 1), and once the key is lost for good the goal is out of
// reach (h = inf, where ignoring it still gives 1: A* would then search every
// reachable state before giving up).
TEST(HFF, NegativePreconditionsAreAtomsOfTheirOwn) {
  auto task = clips::testing::vault_task();
  model::Specification spec(task, "(inside)", model::unit_profile());
  heuristics::FFHeuristic with, without(/*turns=*/true, /*negations=*/false);
  EXPECT_EQ(with.name(), "hff");
  EXPECT_EQ(without.name(), "hff-noneg");
  const pddl::State s0 = task->initial_state();
  with.prepare(spec, s0);
  without.prepare(spec, s0);
  EXPECT_DOUBLE_EQ(with.estimate(s0.data()), 3);
  EXPECT_DOUBLE_EQ(without.estimate(s0.data()), 1);
  const pddl::State held = clips::testing::after(*task, s0, {"(take)"});
  EXPECT_DOUBLE_EQ(with.estimate(held.data()), 2);
  const pddl::State lost = clips::testing::after(*task, held, {"(lose)"});
  EXPECT_EQ(with.estimate(lost.data()), kInf);
  EXPECT_DOUBLE_EQ(without.estimate(lost.data()), 1);
  const pddl::State open = clips::testing::after(*task, held, {"(unlock)"});
  EXPECT_DOUBLE_EQ(with.estimate(open.data()), 1);
}
