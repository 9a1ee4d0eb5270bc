// A small PDDL task whose grounding is wide: one 3-parameter action over N
// objects (N^3 ground actions, all applicable from the start). Every expansion
// generates N^3 children and every h_max estimate walks N^3 actions, so at
// N = 15 one batch of 256 expansions takes minutes: the case where time
// limits must be checked inside expansions and estimates, not between them.
#pragma once

#include <string>

namespace clips::testing {

inline std::string wide_domain_pddl() {
  return R"((define (domain wide)
  (:requirements :strips :typing)
  (:types obj)
  (:predicates (at ?x - obj) (link ?x ?y ?z - obj) (sealed ?x - obj))  ; nothing adds sealed
  (:action join
    :parameters (?x ?y ?z - obj)
    :precondition (and (at ?x) (at ?y))
    :effect (and (link ?x ?y ?z) (at ?z))))
)";
}

// Every object is `at`; the goal asks for `links` disjoint link facts, so the
// optimal plan has `links` steps but h_max sees only 1 until the end.
inline std::string wide_problem_pddl(int objects, int links) {
  std::string objs, init, goal;
  for (int i = 1; i <= objects; ++i) {
    objs += " o" + std::to_string(i);
    init += " (at o" + std::to_string(i) + ")";
  }
  for (int k = 0; k < links; ++k) {
    const int a = 3 * k % objects + 1, b = (3 * k + 1) % objects + 1, c = (3 * k + 2) % objects + 1;
    goal += " (link o" + std::to_string(a) + " o" + std::to_string(b) + " o" + std::to_string(c) + ")";
  }
  return "(define (problem wide-" + std::to_string(objects) + ") (:domain wide)\n  (:objects" + objs +
         " - obj)\n  (:init" + init + ")\n  (:goal (and" + goal + ")))\n";
}

}  // namespace clips::testing
