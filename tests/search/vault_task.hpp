#pragma once
// A vault behind a locked door whose key can be lost for good: the smallest
// task where a negative precondition (not (locked)) matters to a relaxation.
// h* = 3 from the start (take, unlock, enter); no plan once the key is lost.
#include <memory>
#include <string>

#include "pddl/parser.hpp"
#include "pddl/task.hpp"

namespace clips::testing {

inline std::shared_ptr<const pddl::Task> vault_task() {
  static const char* kDomain = R"(
(define (domain vault)
  (:requirements :strips :negative-preconditions)
  (:predicates (inside) (locked) (has-key) (key-here) (lost))
  (:action take :precondition (and (key-here) (not (lost))) :effect (and (has-key) (not (key-here))))
  (:action lose :precondition (has-key) :effect (and (not (has-key)) (lost)))
  (:action unlock :precondition (and (has-key) (locked)) :effect (not (locked)))
  (:action enter :precondition (not (locked)) :effect (inside)))
)";
  static const char* kProblem = "(define (problem vault-1) (:domain vault) (:init (locked) (key-here)) (:goal (inside)))";
  auto d = std::make_shared<const pddl::Domain>(pddl::parse_domain(kDomain, "<vault>"));
  auto p = std::make_shared<const pddl::Problem>(pddl::parse_problem(*d, kProblem, "<vault-1>"));
  return std::make_shared<const pddl::Task>(d, p);
}

// `s` after the named actions, each applicable in turn.
inline pddl::State after(const pddl::Task& task, pddl::State s, std::initializer_list<const char*> names) {
  for (const char* name : names)
    for (pddl::ActionId a : task.applicable_actions(s))
      if (task.action_name(a) == name) {
        s = task.apply(s, a);
        break;
      }
  return s;
}

}  // namespace clips::testing
