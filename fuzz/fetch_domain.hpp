#pragma once
// The small two-agent fetch domain and problem the pack-level fuzz targets
// (pack, pack_roles, cost_profiles, quantified_goals) check their inputs
// against: two agents taking turns, two rooms, three items of two kinds.
#include <memory>

#include "pddl/parser.hpp"
#include "pddl/task.hpp"

namespace clips::fuzz {

inline const char* const kFetchDomain = R"((define (domain fetch)
  (:requirements :typing :negative-preconditions :equality)
  (:types human robot - agent tool part - item item agent room colour - object)
  (:predicates (at ?a - agent ?r - room) (in ?i - item ?r - room) (holding ?a - agent ?i - item)
               (iscolour ?i - item ?c - colour) (active ?a - agent) (next ?a - agent ?b - agent)
               (done ?i - item))
  (:functions (total-cost))
  (:action move :parameters (?a - agent ?x - room ?y - room)
   :precondition (and (active ?a) (at ?a ?x) (not (= ?x ?y)))
   :effect (and (not (at ?a ?x)) (at ?a ?y) (not (active ?a))
                (forall (?b - agent) (when (next ?a ?b) (active ?b))) (increase (total-cost) 1)))
  (:action pickup :parameters (?a - agent ?i - item ?r - room)
   :precondition (and (active ?a) (at ?a ?r) (in ?i ?r))
   :effect (and (not (in ?i ?r)) (holding ?a ?i) (not (active ?a))
                (forall (?b - agent) (when (next ?a ?b) (active ?b))) (increase (total-cost) 1)))
  (:action handover :parameters (?a - agent ?b - agent ?i - item ?r - room)
   :precondition (and (active ?a) (not (= ?a ?b)) (at ?a ?r) (at ?b ?r) (holding ?a ?i))
   :effect (and (not (holding ?a ?i)) (holding ?b ?i) (not (active ?a)) (active ?b)
                (increase (total-cost) 1)))
  (:action finish :parameters (?a - human ?i - item)
   :precondition (and (active ?a) (holding ?a ?i))
   :effect (and (done ?i) (not (active ?a)) (forall (?b - agent) (when (next ?a ?b) (active ?b)))))
  (:action wait :parameters (?a - agent)
   :precondition (active ?a)
   :effect (and (not (active ?a)) (forall (?b - agent) (when (next ?a ?b) (active ?b)))
                (increase (total-cost) 1)))))";

inline const char* const kFetchProblem = R"((define (problem fetch-1) (:domain fetch)
  (:objects human - human robot - robot hall shed - room red blue - colour
            saw1 - tool plank1 plank2 - part)
  (:init (active human) (next human robot) (next robot human) (at human hall) (at robot shed)
         (in saw1 shed) (in plank1 shed) (in plank2 hall)
         (iscolour saw1 red) (iscolour plank1 blue) (iscolour plank2 red) (= (total-cost) 0))
  (:goal (done plank1))))";

inline const clips::pddl::Task& fetch_task() {
  using namespace clips::pddl;
  static const Task task = [] {
    auto domain = std::make_shared<Domain>(parse_domain(kFetchDomain, "<fetch domain>"));
    auto problem = std::make_shared<Problem>(parse_problem(*domain, kFetchProblem, "<fetch problem>"));
    return Task(domain, problem);
  }();
  return task;
}

}  // namespace clips::fuzz
