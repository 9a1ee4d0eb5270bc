#pragma once
// The includes, helpers and fixtures of the search tests in lmcut_test.cpp, shared by
// the files of that name in tests/search/ and its label folders
// (docs/testing.md, "Labels").
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

namespace lmcut_test {

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

}  // namespace lmcut_test
using namespace lmcut_test;
