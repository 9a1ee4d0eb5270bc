// LM-cut (heuristics/lmcut.hpp): exact on small hand-checked cases, never
// above the optimal cost on random reachable states of several domains, and
// A* with it finds the optimal costs A* with h_max finds on every problem and
// candidate goal of the workshop. Also the mutex table it prunes goals with.
#include <gtest/gtest.h>

#include <chrono>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <random>

#include "data/dataset.hpp"
#include "dkg_profiles.hpp"
#include "heuristics/basic.hpp"
#include "heuristics/lmcut.hpp"
#include "heuristics/mutex.hpp"
#include "pddl/parser.hpp"
#include "search/astar.hpp"
#include "test_paths.hpp"
#include "vault_task.hpp"

using namespace clips;

namespace {

namespace fs = std::filesystem;

std::shared_ptr<const pddl::Task> task_of(const std::string& domain, const std::string& problem) {
  auto d = std::make_shared<const pddl::Domain>(pddl::parse_domain(domain, "<domain>"));
  auto p = std::make_shared<const pddl::Problem>(pddl::parse_problem(*d, problem, "<problem>"));
  return std::make_shared<const pddl::Task>(d, p);
}

// The optimal cost from s by A* with h_max (consistent), NaN past the budget.
double optimal_cost(const model::Specification& spec, const pddl::State& s, size_t budget = 200000) {
  heuristics::HMaxHeuristic h;
  search::SearchOptions o;
  o.max_nodes = budget;
  auto r = search::plan(spec, h, s, o);
  if (r.status == search::SearchStatus::Success) return r.cost;
  if (r.status == search::SearchStatus::Failure) return model::kInf;
  return std::nan("");
}

double lmcut(const model::Specification& spec, const pddl::State& s, bool turns = true) {
  heuristics::LmCutHeuristic h(turns);
  h.prepare(spec, s);
  return h.estimate(s.data());
}

const char* kChainDomain = R"(
(define (domain chain)
  (:requirements :typing :action-costs)
  (:types place)
  (:predicates (at ?p - place) (link ?a - place ?b - place) (visited ?p - place))
  (:functions (total-cost) - number)
  (:action go :parameters (?a - place ?b - place)
   :precondition (and (at ?a) (link ?a ?b))
   :effect (and (not (at ?a)) (at ?b) (increase (total-cost) 2)))
  (:action mark :parameters (?p - place)
   :precondition (at ?p)
   :effect (and (visited ?p) (increase (total-cost) 1))))
)";

const char* kChainProblem = R"(
(define (problem chain-1) (:domain chain)
  (:objects a b c - place)
  (:init (at a) (link a b) (link b a) (link b c) (link c b))
  (:goal (and (visited b) (visited c))))
)";

std::string workshop_dir() { return paths::source_dir() + "/data/datasets/workshop"; }

std::vector<std::string> goal_set(const std::string& dir, const std::string& problem) {
  std::ifstream in(fs::path(dir) / "goals" / "sets" / (problem + ".txt"));
  std::vector<std::string> out;
  for (std::string label; in >> label;) out.push_back(label);
  return out;
}

std::string goal_text(const std::string& dir, const std::string& label) {
  std::ifstream in(fs::path(dir) / "goals" / "definitions" / (label + ".pddl"));
  return std::string((std::istreambuf_iterator<char>(in)), {});
}

}  // namespace

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

// Admissibility: on states along random walks (with and without the robot
// frozen, on either agent's turn) LM-cut never exceeds the optimal cost, on
// the workshop, the storeroom profiling domain and the Doors-Keys-Gems
// examples (numeric grid positions, the paper's costs with a 0.6 wait).
TEST(LmCut, AdmissibleOnRandomWalks) {
  struct Case {
    std::string dir, problem;
    std::vector<std::string> goals;
    int profile;  // 0: unit; else the mDKG profile
  };
  std::vector<Case> cases = {
      {workshop_dir(), "1", {}, 0},
      {workshop_dir(), "3", {}, 0},
      {workshop_dir(), "8", {}, 0},
      {paths::source_dir() + "/bench/data/storeroom", "4", {}, 0},
      {paths::examples_dir() + "/doors-keys-gems", "e1", {"(has human gem1)", "(has human gem3)"}, 1},
      {paths::examples_dir() + "/doors-keys-gems", "e1", {"(has human gem2)"}, 4},
  };
  std::mt19937 rng(5);
  int checked = 0, exact = 0;
  for (const Case& c : cases) {
    auto ds = data::Dataset::load(c.dir);
    auto task = ds.task(c.problem);
    std::vector<std::string> goals = c.goals;
    if (goals.empty())
      for (const auto& label : goal_set(c.dir, c.problem)) goals.push_back(goal_text(c.dir, label));
    const model::CostProfile profile = c.profile ? fixtures::dkg_profile(c.profile) : model::unit_profile();
    for (const auto& g : goals) {
      model::Specification spec(task, g, profile);
      heuristics::LmCutHeuristic h;
      h.prepare(spec, task->initial_state());
      pddl::State s = task->initial_state();
      for (int step = 0; step < 16; ++step) {
        if (step % 4 == 0) {
          for (bool freeze : {false, true}) {
            const pddl::State t = freeze ? model::freeze(*task, s, "robot") : s;
            const double truth = optimal_cost(spec, t, 20000);
            if (std::isnan(truth)) continue;
            const double est = h.estimate(t.data());
            EXPECT_LE(est, truth + 1e-9) << c.dir << " " << c.problem << " " << g << " step " << step
                                         << (freeze ? " frozen" : "");
            if (truth < model::kInf && std::abs(est - truth) < 1e-9) ++exact;
            ++checked;
          }
        }
        auto acts = task->applicable_actions(s);
        if (acts.empty() || spec.is_goal(s)) break;
        s = task->apply(s, acts[rng() % acts.size()]);
      }
    }
  }
  std::cout << "LM-cut checked against h* on " << checked << " states, exact on " << exact << "\n";
  EXPECT_GE(checked, 100);
}

// A* with LM-cut finds the same optimal cost as A* with h_max for every
// candidate goal of every workshop problem, from the initial state, and
// expands fewer states.
TEST(LmCut, SameOptimalCostsAsHMaxOnTheWorkshop) {
  const std::string dir = workshop_dir();
  auto ds = data::Dataset::load(dir);
  size_t goals = 0, exp_lmcut = 0, exp_hmax = 0;
  double t_lmcut = 0, t_hmax = 0;
  for (auto& set : fs::directory_iterator(fs::path(dir) / "goals" / "sets")) {
    const std::string problem = set.path().stem().string();
    auto task = ds.task(problem);
    for (const auto& label : goal_set(dir, problem)) {
      SCOPED_TRACE("problem " + problem + ", goal " + label);
      model::Specification spec(task, goal_text(dir, label), model::unit_profile());
      heuristics::HMaxHeuristic hmax;
      heuristics::LmCutHeuristic lm;
      auto a = search::plan(spec, hmax, task->initial_state());
      auto b = search::plan(spec, lm, task->initial_state());
      ASSERT_EQ(a.status, search::SearchStatus::Success);
      ASSERT_EQ(b.status, search::SearchStatus::Success);
      EXPECT_DOUBLE_EQ(a.cost, b.cost);
      EXPECT_TRUE(spec.is_goal(pddl::simulate(*task, task->initial_state(), b.plan).states.back()));
      exp_hmax += a.expanded;
      exp_lmcut += b.expanded;
      t_hmax += a.seconds;
      t_lmcut += b.seconds;
      ++goals;
    }
  }
  std::cout << goals << " goals: h_max " << exp_hmax << " expansions (" << t_hmax << " s), LM-cut " << exp_lmcut
            << " (" << t_lmcut << " s)\n";
  EXPECT_GE(goals, 30u);
  EXPECT_LT(exp_lmcut, exp_hmax);
}
