#include "search/astar_test.hpp"

TEST(AStar, HMaxMatchesUniformCostSearchOnExampleProblems) {
  auto ds = data::Dataset::load(paths::examples_dir() + "/doors-keys-gems");
  for (const char* p : {"e1", "e2"})
    for (int g = 1; g <= 4; ++g)
      for (int c = 1; c <= 4; ++c) {
        auto spec = spec_for(ds, p, g, c);
        heuristics::HMaxHeuristic h;
        auto r = search::plan(*spec, h, spec->task().initial_state());
        double ucs = true_cost(*spec, spec->task().initial_state());
        ASSERT_FALSE(std::isnan(ucs));
        if (ucs == model::kInf) {
          EXPECT_EQ(r.status, search::SearchStatus::Failure);
          continue;
        }
        ASSERT_EQ(r.status, search::SearchStatus::Success) << p << " gem" << g << " C" << c;
        EXPECT_NEAR(r.cost, ucs, 1e-9) << p << " gem" << g << " C" << c;
        // The plan is valid and reaches the goal at the reported cost.
        auto sim = pddl::simulate(spec->task(), spec->task().initial_state(), r.plan);
        EXPECT_TRUE(spec->is_goal(sim.states.back()));
        double c2 = 0;
        for (auto a : r.plan) c2 += spec->cost(a);
        EXPECT_NEAR(c2, r.cost, 1e-9);
      }
}
