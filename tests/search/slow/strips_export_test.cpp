#include "search/strips_export_test.hpp"

TEST(StripsExport, SameOptimalCostOnExampleProblems) {
  auto ds = examples();
  for (const char* p : {"e1", "e2"})
    for (int g = 1; g <= 4; ++g)
      for (int c = 1; c <= 4; ++c) {
        auto task = ds.task(p);
        check_equivalent(task, task->initial_state(), g, c, p);
      }
}

// Mid-plan start states: the robot may be active, items held or consumed and
// doors already open.
TEST(StripsExport, SameOptimalCostFromMidPlanStates) {
  auto ds = examples();
  for (const char* p : {"e1", "e2"})
    for (int g = 1; g <= 4; ++g) {
      auto task = ds.task(p);
      model::Specification spec(task, "(has human gem" + std::to_string(g) + ")", fixtures::dkg_profile(3));
      heuristics::HMaxHeuristic h;
      auto r = search::plan(spec, h, task->initial_state());
      // Every gem of the examples is reachable: a failed search is a bug, not a case to skip.
      ASSERT_EQ(r.status, search::SearchStatus::Success) << p << " gem" << g << ": " << search::to_string(r.status);
      ASSERT_GE(r.plan.size(), 2u) << p << " gem" << g;
      auto sim = pddl::simulate(*task, task->initial_state(), r.plan);
      for (size_t k = 1; k < sim.states.size(); k += 3)
        EXPECT_TRUE(check_equivalent(task, sim.states[k], g, 1 + static_cast<int>(k % 4),
                                     std::string(p) + " step " + std::to_string(k)));
    }
}

TEST(StripsExport, ConjunctiveGoalsAndUnsupportedGoals) {
  auto ds = examples();
  auto task = ds.task("e1");
  auto s0 = task->initial_state();
  // A conjunction of has atoms is exported and stays equivalent.
  std::string goal = "(and (has human gem1) (has human gem2))";
  auto ex = domains::dkg::export_strips(*task, s0, goal, fixtures::dkg_profile(1));
  EXPECT_EQ(ex.goal, "(and (has human gem1) (has human gem2))");
  model::Specification orig(task, goal, fixtures::dkg_profile(1));
  heuristics::HMaxHeuristic h1, h2;
  auto r1 = search::plan(orig, h1, s0);
  auto d = std::make_shared<pddl::Domain>(pddl::parse_domain(ex.domain, "d"));
  auto p = std::make_shared<pddl::Problem>(pddl::parse_problem(*d, ex.problem, "p"));
  auto et = std::make_shared<pddl::Task>(d, p);
  model::Specification es(et, goal, model::task_costs_profile());
  auto r2 = search::plan(es, h2, et->initial_state());
  ASSERT_EQ(r1.status, search::SearchStatus::Success);
  ASSERT_EQ(r2.status, search::SearchStatus::Success);
  EXPECT_NEAR(r2.cost / ex.cost_scale, r1.cost, 1e-9);

  auto prof = fixtures::dkg_profile(1);
  for (const char* bad : {"(or (has human gem1) (has human gem2))", "(not (has human gem1))", "(locked door1)",
                          "(has human)", "(has human door1)", "(has nobody gem1)", "(and)"}) {
    try {
      domains::dkg::export_strips(*task, s0, bad, prof);
      ADD_FAILURE() << "accepted " << bad;
    } catch (const InputError& e) {
      EXPECT_NE(std::string(e.what()).find("has"), std::string::npos) << bad << ": " << e.what();
    }
  }
  EXPECT_THROW(domains::dkg::export_strips(*task, s0, "(has human gem1)", model::task_costs_profile()), InputError);
}
