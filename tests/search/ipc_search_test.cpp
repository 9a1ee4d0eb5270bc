#include "search/ipc_search_test.hpp"

namespace ipc_search_test {
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

}  // namespace ipc_search_test
