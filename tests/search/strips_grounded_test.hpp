#pragma once
// The includes, helpers and fixtures of the search tests in strips_grounded_test.cpp, shared by
// the files of that name in tests/search/ and its label folders
// (docs/testing.md, "Labels").
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

namespace strips_grounded_test {

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

}  // namespace strips_grounded_test
using namespace strips_grounded_test;
