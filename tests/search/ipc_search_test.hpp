#pragma once
// The includes, helpers and fixtures of the search tests in ipc_search_test.cpp, shared by
// the files of that name in tests/search/ and its label folders
// (docs/testing.md, "Labels").
// Search over the PDDL features of issue 64: derived predicates under h_max,
// h_FF and LM-cut (admissible ones find the optimal cost uniform-cost search
// finds), negative goal literals in LM-cut, and a state with more than 65,535
// applicable actions in the shared state graph.
#include <gtest/gtest.h>

#include <memory>
#include <string>

#include "heuristics/basic.hpp"
#include "heuristics/lmcut.hpp"
#include "pddl/parser.hpp"
#include "search/astar.hpp"
#include "search/state_graph.hpp"

using namespace clips;

namespace ipc_search_test {

std::shared_ptr<const pddl::Task> task_of(const std::string& domain, const std::string& problem) {
  auto d = std::make_shared<const pddl::Domain>(pddl::parse_domain(domain, "<domain>"));
  auto p = std::make_shared<const pddl::Problem>(pddl::parse_problem(*d, problem, "<problem>"));
  return std::make_shared<const pddl::Task>(d, p);
}

search::SearchResult solve(const model::Specification& spec, heuristics::Heuristic& h) {
  search::SearchOptions o;
  o.max_nodes = 200000;
  return search::plan(spec, h, spec.task().initial_state(), o);
}

// Rooms in a grid with doors that must be unlocked from a reachable room
// ((reachable ?r) is derived, recursively); keys are fetched from reachable
// rooms; the goal asks for rooms to be reachable and one not to be sealed.
const char* kKeysDomain = R"((define (domain keyrooms)
  (:requirements :adl :derived-predicates :action-costs)
  (:types room key)
  (:predicates (start ?r - room) (door ?a ?b - room) (open ?a ?b - room) (key-in ?k - key ?r - room)
               (has ?k - key) (fits ?k - key ?a ?b - room) (reachable ?r - room) (sealed ?r - room))
  (:functions (total-cost))
  (:derived (reachable ?r - room)
    (or (start ?r) (exists (?s - room) (and (reachable ?s) (or (open ?s ?r) (open ?r ?s))))))
  (:derived (sealed ?r - room) (not (reachable ?r)))
  (:action take :parameters (?k - key ?r - room)
    :precondition (and (key-in ?k ?r) (reachable ?r))
    :effect (and (not (key-in ?k ?r)) (has ?k) (increase (total-cost) 1)))
  (:action unlock :parameters (?k - key ?a ?b - room)
    :precondition (and (has ?k) (fits ?k ?a ?b) (door ?a ?b) (reachable ?a) (not (open ?a ?b)))
    :effect (and (open ?a ?b) (increase (total-cost) 2))))
)";
const char* kKeysProblem = R"((define (problem kr) (:domain keyrooms)
  (:objects r1 r2 r3 r4 r5 - room k1 k2 k3 - key)
  (:init (start r1) (door r1 r2) (door r2 r3) (door r1 r4) (door r4 r5) (door r3 r5)
         (key-in k1 r1) (key-in k2 r2) (key-in k3 r4)
         (fits k1 r1 r2) (fits k2 r2 r3) (fits k1 r1 r4) (fits k3 r4 r5) (fits k2 r3 r5)
         (= (total-cost) 0))
  (:goal (and (reachable r5) (not (sealed r3)))))
)";

}  // namespace ipc_search_test
using namespace ipc_search_test;
