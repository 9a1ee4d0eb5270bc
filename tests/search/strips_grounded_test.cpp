// The generic STRIPS export (domains/strips.hpp, `clips export-strips` for
// packs without their own compilation): the exported domain and problem,
// read back by our own parser and solved by A* with LM-cut, have the optimal
// cost `clips plan` finds on the original task, for every problem and
// candidate goal of the workshop; exported plans map back to valid original
// plans. A hand-made task covers what the workshop does not use: disjunctive
// preconditions, conditional effects with dynamic conditions, negative goals.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <iostream>

#include "data/dataset.hpp"
#include "domains/strips.hpp"
#include "heuristics/basic.hpp"
#include "heuristics/lmcut.hpp"
#include "pddl/parser.hpp"
#include "pddl/plan.hpp"
#include "search/astar.hpp"
#include "test_paths.hpp"

using namespace clips;

namespace {

namespace fs = std::filesystem;

std::shared_ptr<const pddl::Task> read_task(const std::string& domain, const std::string& problem) {
  auto d = std::make_shared<const pddl::Domain>(pddl::parse_domain(domain, "<exported domain>"));
  auto p = std::make_shared<const pddl::Problem>(pddl::parse_problem(*d, problem, "<exported problem>"));
  return std::make_shared<const pddl::Task>(d, p);
}

struct Solved {
  search::SearchResult original, exported;
  double scale = 1;
};

// Optimal plans on the task and on its export from `start`, and the exported
// plan replayed on the task (valid, reaching the goal at the same cost).
Solved solve_both(const std::shared_ptr<const pddl::Task>& task, const pddl::State& start, const std::string& goal,
                  const model::CostProfile& profile, bool lmcut) {
  Solved out;
  model::Specification spec(task, goal, profile);
  std::unique_ptr<heuristics::Heuristic> h1, h2;
  if (lmcut) {
    h1 = std::make_unique<heuristics::LmCutHeuristic>();
    h2 = std::make_unique<heuristics::LmCutHeuristic>();
  } else {
    h1 = std::make_unique<heuristics::BlindHeuristic>();
    h2 = std::make_unique<heuristics::BlindHeuristic>();
  }
  out.original = search::plan(spec, *h1, start);
  const domains::StripsExport ex = domains::export_grounded_strips(*task, start, goal, profile);
  out.scale = ex.cost_scale;
  auto etask = read_task(ex.domain, ex.problem);
  model::Specification espec(etask, ex.goal, model::task_costs_profile());
  out.exported = search::plan(espec, *h2, etask->initial_state());
  EXPECT_EQ(out.original.status, out.exported.status);
  if (out.original.status != search::SearchStatus::Success || out.exported.status != search::SearchStatus::Success)
    return out;
  EXPECT_NEAR(out.exported.cost / ex.cost_scale, out.original.cost, 1e-9);
  pddl::State s = start;
  double cost = 0;
  for (pddl::ActionId a : out.exported.plan) {
    const std::string& text = ex.original_actions.at(etask->action_name(a).substr(1, etask->action_name(a).size() - 2));
    if (text.empty()) continue;  // the export's own goal action
    auto oa = task->find_action(text);
    EXPECT_TRUE(oa.has_value()) << text;
    if (!oa) return out;
    EXPECT_TRUE(task->applicable(*oa, s.data())) << text;
    if (!task->applicable(*oa, s.data())) return out;
    cost += spec.cost(*oa);
    s = task->apply(s, *oa);
  }
  EXPECT_TRUE(spec.is_goal(s));
  EXPECT_NEAR(cost, out.original.cost, 1e-9);
  return out;
}

const char* kSwitchDomain = R"(
(define (domain switches)
  (:requirements :typing :negative-preconditions :disjunctive-preconditions :conditional-effects :action-costs)
  (:types lamp)
  (:predicates (on ?l - lamp) (broken ?l - lamp) (linked ?a - lamp ?b - lamp) (power))
  (:functions (total-cost) - number)
  (:action flip :parameters (?l - lamp)
   :precondition (or (power) (not (broken ?l)))
   :effect (and (when (on ?l) (not (on ?l))) (when (not (on ?l)) (on ?l))
                (forall (?m - lamp) (when (and (linked ?l ?m) (on ?m)) (broken ?m)))
                (increase (total-cost) 2)))
  (:action repair :parameters (?l - lamp)
   :precondition (and (broken ?l) (not (on ?l)))
   :effect (and (not (broken ?l)) (increase (total-cost) 3)))
  (:action toggle-power :parameters ()
   :precondition (and)
   :effect (and (when (power) (not (power))) (when (not (power)) (power)) (increase (total-cost) 1))))
)";

const char* kSwitchProblem = R"(
(define (problem switches-1) (:domain switches)
  (:objects a b c - lamp)
  (:init (on a) (broken b) (linked a b) (linked b c) (linked c a))
  (:goal (and (on b) (on c) (not (broken a)))))
)";

}  // namespace

// Exhaustively (blind A*) from the start and from states along random walks.
TEST(StripsGrounded, DisjunctionsConditionalEffectsAndNegativeGoals) {
  auto task = read_task(kSwitchDomain, kSwitchProblem);
  const std::vector<std::string> goals = {"(and (on b) (on c) (not (broken a)))", "(or (broken c) (not (on a)))",
                                          "(and (not (power)) (on a) (on b))"};
  pddl::State s = task->initial_state();
  int solved = 0;
  for (int step = 0; step < 6; ++step) {
    for (const auto& g : goals) {
      SCOPED_TRACE(g + " step " + std::to_string(step));
      auto r = solve_both(task, s, g, model::task_costs_profile(), /*lmcut=*/false);
      solved += r.original.status == search::SearchStatus::Success;
      // LM-cut is admissible on the export too (and the original task has
      // conditional effects, which it reads as plain adds).
      auto l = solve_both(task, s, g, model::task_costs_profile(), /*lmcut=*/true);
      EXPECT_EQ(l.original.cost, r.original.cost);
    }
    auto acts = task->applicable_actions(s);
    ASSERT_FALSE(acts.empty());
    s = task->apply(s, acts[static_cast<size_t>(step * 7 + 3) % acts.size()]);
  }
  EXPECT_GE(solved, 12);
}

// Every problem and candidate goal of the workshop, unit costs and a 0.6
// wait (scaled by 5), from the initial state and from where each plan's
// observed part ends: the same optimal cost, and the time ratio of solving
// the export to solving the task (both A* with LM-cut; on the export LM-cut
// has no turn structure to read, since its actions name no agent).
TEST(StripsGrounded, SameOptimalCostsAsClipsPlanOnTheWorkshop) {
  const fs::path dir = fs::path(paths::source_dir()) / "data" / "datasets" / "workshop";
  auto ds = data::Dataset::load(dir.string());
  model::CostProfile cheap_wait = model::unit_profile();
  cheap_wait.name = "wait-0.6";
  cheap_wait.costs[{"human", "wait"}] = 0.6;
  cheap_wait.costs[{"robot", "wait"}] = 0.6;
  int checked = 0;
  double t_task = 0, t_export = 0;
  for (auto& set : fs::directory_iterator(dir / "goals" / "sets")) {
    const std::string problem = set.path().stem().string();
    auto task = ds.task(problem);
    std::vector<pddl::State> starts = {task->initial_state()};
    for (const auto& p : ds.plans())
      if (p.problem_id == problem) starts.push_back(pddl::simulate(*task, task->initial_state(), p.observed).states.back());
    std::ifstream in(set.path());
    for (std::string label; in >> label;) {
      std::ifstream def(dir / "goals" / "definitions" / (label + ".pddl"));
      const std::string goal((std::istreambuf_iterator<char>(def)), {});
      for (size_t k = 0; k < starts.size(); ++k)
        for (const auto& profile : {model::unit_profile(), cheap_wait}) {
          if (k > 0 && profile.name != "unit") continue;  // mid-plan states: unit costs only
          SCOPED_TRACE("problem " + problem + " goal " + label + " start " + std::to_string(k) + " " + profile.name);
          auto r = solve_both(task, starts[k], goal, profile, /*lmcut=*/true);
          ASSERT_EQ(r.original.status, search::SearchStatus::Success);
          t_task += r.original.seconds;
          t_export += r.exported.seconds;
          ++checked;
        }
    }
  }
  std::cout << checked << " workshop tasks: A*(LM-cut) " << t_task << " s on the tasks, " << t_export
            << " s on their exports (ratio " << t_export / t_task << ")\n";
  EXPECT_GE(checked, 100);
}

// Numeric tasks are refused with a message naming the way out.
TEST(StripsGrounded, NumericTasksAreRefused) {
  auto ds = data::Dataset::load(paths::examples_dir() + "/doors-keys-gems");
  auto task = ds.task("e1");
  try {
    domains::export_grounded_strips(*task, task->initial_state(), "(has human gem1)", model::unit_profile());
    FAIL() << "no error";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("numeric"), std::string::npos) << e.what();
  }
}
