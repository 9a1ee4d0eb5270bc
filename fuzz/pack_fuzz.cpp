// The domain declaration file (pack.json). The input is the file's text: it
// is parsed, checked against a small two-agent fetch domain, built into a
// pack (its "code" may pick compiled hooks), and asked what the rest of clips
// asks a pack about one grounded problem: goals, profiles, heuristics,
// literal candidates, options, the state text. Its language.goal_atoms
// templates (given, or derived from the salient actions' effects as
// pack_for_domain does) are expanded for every literal candidate into the
// goal formula the listener plans for, and compiled against the task: a pack
// the checks accept must not fail there with anything but an InputError
// (issue 46: "(holding $1 $7)" passed `validate` and failed in `listen`).
// Whatever the file says, the pack either is rejected with an InputError or
// answers without crashing.
#include <memory>

#include "domains/pack.hpp"
#include "fuzz/fuzz_target.hpp"
#include "language/commands/command.hpp"
#include "pddl/parser.hpp"
#include "pddl/task.hpp"

namespace {

constexpr size_t kMaxInputBytes = 16384;
constexpr size_t kMaxGoalFormulas = 64;

const char* const kDomain = R"((define (domain fetch)
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

const char* const kProblem = R"((define (problem fetch-1) (:domain fetch)
  (:objects human - human robot - robot hall shed - room red blue - colour
            saw1 - tool plank1 plank2 - part)
  (:init (active human) (next human robot) (next robot human) (at human hall) (at robot shed)
         (in saw1 shed) (in plank1 shed) (in plank2 hall)
         (iscolour saw1 red) (iscolour plank1 blue) (iscolour plank2 red) (= (total-cost) 0))
  (:goal (done plank1))))";

const clips::pddl::Task& fetch_task() {
  using namespace clips::pddl;
  static const Task task = [] {
    auto domain = std::make_shared<Domain>(parse_domain(kDomain, "<fetch domain>"));
    auto problem = std::make_shared<Problem>(parse_problem(*domain, kProblem, "<fetch problem>"));
    return Task(domain, problem);
  }();
  return task;
}

}  // namespace

CLIPS_FUZZ_TARGET(pack) {
  using namespace clips;
  if (size > kMaxInputBytes) return 0;
  const pddl::Task& task = fetch_task();
  try {
    domains::PackSpec spec = domains::parse_pack_spec(fuzz::as_text(data, size), "<pack.json>");
    domains::check_pack_against(spec, task.domain());
    domains::derive_goal_atoms(spec, task.domain());
    const domains::PackPtr pack = domains::make_pack(std::move(spec));
    pack->check_problem(task, "<fetch problem>");
    const pddl::State s = task.initial_state();
    if (pack->spec().goals.source != domains::GoalSource::GoalSets) {
      const auto goals = pack->problem_goals(task, "<fetch problem>");
      if (goals.empty()) __builtin_trap();  // an empty candidate set must be an InputError
    }
    (void)pack->profiles_for("");
    for (const auto& name : pack->heuristic_names()) {
      auto h = pack->make_heuristic(name, task);
      if (!h) __builtin_trap();
    }
    size_t expanded = 0;
    for (const auto& term : pack->literal_candidates(task, s)) {
      if (++expanded > kMaxGoalFormulas) break;
      commands::Command command;
      command.actions = {term};
      // std::invalid_argument here (a template the checks let through) is a finding.
      const std::string formula = command.to_goal_formula(pack->spec().language);
      (void)task.compile_text(formula, "<goal of " + term.name + ">").holds(s);
    }
    (void)pack->qualifier_of(task);
    for (pddl::ActionId a : task.applicable_actions(s)) (void)pack->option_of(task, a, "");
    (void)pack->is_option_object(task, "plank1", "");
    (void)pack->describe_state(task, s);
    (void)pack->object_list(task);
  } catch (const InputError&) {
  }
  return 0;
}
