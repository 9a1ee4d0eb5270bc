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

namespace {

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

TEST(DerivedSearch, AdmissibleHeuristicsFindTheUniformCostOptimum) {
  auto t = task_of(kKeysDomain, kKeysProblem);
  ASSERT_GT(t->num_axioms(), 0);
  model::Specification spec(t, t->problem().goal_sexpr->str(), model::task_costs_profile());
  heuristics::BlindHeuristic blind;
  const auto ucs = solve(spec, blind);
  ASSERT_EQ(ucs.status, search::SearchStatus::Success);
  // Take k1 (1), open r1-r2 (2), take k2 (1), open r2-r3 (2), and k2 also
  // opens r3-r5 (2): 8 (through r4 it would be 11).
  EXPECT_EQ(ucs.cost, 8);
  heuristics::HMaxHeuristic hmax;
  heuristics::LmCutHeuristic lmcut;
  EXPECT_EQ(solve(spec, hmax).cost, ucs.cost);
  EXPECT_EQ(solve(spec, lmcut).cost, ucs.cost);
  // Never above the optimal cost from any state on the optimal plan.
  pddl::State s = t->initial_state();
  double left = ucs.cost;
  for (size_t i = 0; i <= ucs.plan.size(); ++i) {
    hmax.prepare(spec, s);
    lmcut.prepare(spec, s);
    EXPECT_LE(hmax.estimate(s.data()), left + 1e-9) << "step " << i;
    EXPECT_LE(lmcut.estimate(s.data()), left + 1e-9) << "step " << i;
    if (i == ucs.plan.size()) break;
    left -= spec.cost(ucs.plan[i]);
    s = t->apply(s, ucs.plan[i]);
  }
  EXPECT_TRUE(spec.is_goal(s));
  // h_FF plans too (not necessarily optimally).
  heuristics::FFHeuristic ff;
  EXPECT_EQ(solve(spec, ff).status, search::SearchStatus::Success);
  // LM-cut is informative over the axioms: above 0 at the start.
  lmcut.prepare(spec, t->initial_state());
  EXPECT_GT(lmcut.estimate(t->initial_state().data()), 0);
}

TEST(NegativeGoals, LmCutCountsWhatMakesThemTrue) {
  const char* dom = R"((define (domain gates) (:requirements :strips :negative-preconditions)
  (:predicates (pending ?g) (ready ?g))
  (:action prepare :parameters (?g) :precondition (not (ready ?g)) :effect (ready ?g))
  (:action run :parameters (?g) :precondition (and (ready ?g) (pending ?g)) :effect (not (pending ?g))))
)";
  auto t = task_of(dom, "(define (problem g) (:domain gates) (:objects a b c) (:init (pending a) (pending b) (pending c))"
                        " (:goal (and (not (pending a)) (not (pending b)) (not (pending c)))))");
  model::Specification spec(t, t->problem().goal_sexpr->str(), model::unit_profile());
  heuristics::LmCutHeuristic h;
  h.prepare(spec, t->initial_state());
  // Each gate needs prepare and run: 6, and LM-cut sees all of it.
  EXPECT_EQ(h.estimate(t->initial_state().data()), 6);
  EXPECT_EQ(solve(spec, h).cost, 6);
}

TEST(StateGraph, AStateWithMoreThan65535SuccessorsIsStored) {
  // 260 x 260 = 67,600 applicable actions in the initial state.
  std::string objs;
  for (int i = 0; i < 260; ++i) objs += " o" + std::to_string(i);
  auto t = task_of(R"((define (domain wide) (:requirements :strips)
    (:predicates (done) (item ?x))
    (:action mark :parameters (?x ?y) :precondition (and (item ?x) (item ?y)) :effect (done))))",
                   "(define (problem w) (:domain wide) (:objects" + objs + ") (:init" +
                       [&] {
                         std::string s;
                         for (int i = 0; i < 260; ++i) s += " (item o" + std::to_string(i) + ")";
                         return s;
                       }() +
                       ") (:goal (done)))");
  ASSERT_EQ(t->num_actions(), 67600);
  search::StateGraph g(t);
  const int root = g.insert(t->initial_state().data());
  const auto succ = g.successors(root);
  ASSERT_EQ(succ.size(), 67600u);
  EXPECT_EQ(succ.front().action, 0);
  EXPECT_EQ(succ.back().action, 67599);
  // Every successor is the one state where (done) holds; a second wide
  // state after it is stored apart.
  EXPECT_EQ(succ.front().child, succ.back().child);
  EXPECT_EQ(g.successors(succ.front().child).size(), 67600u);
  EXPECT_EQ(g.successors(root).size(), 67600u);
}

}  // namespace
