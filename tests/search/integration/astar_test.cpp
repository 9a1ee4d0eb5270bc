#include "search/astar_test.hpp"

TEST(HMax, AdmissibleAndConsistentOnRandomWalks) {
  auto ds = data::Dataset::load(paths::examples_dir() + "/doors-keys-gems");
  std::mt19937 rng(7);
  for (int c : {1, 4}) {
    auto spec = spec_for(ds, "e1", 3, c);
    heuristics::HMaxHeuristic h;
    h.prepare(*spec, spec->task().initial_state());
    pddl::State s = spec->task().initial_state();
    for (int step = 0; step < 60; ++step) {
      auto acts = spec->task().applicable_actions(s);
      ASSERT_FALSE(acts.empty());
      double hs = h.estimate(s.data());
      for (auto a : acts) {
        auto t = spec->task().apply(s, a);
        EXPECT_LE(hs, spec->cost(a) + h.estimate(t.data()) + 1e-9) << "consistency";
      }
      if (step % 10 == 0) {
        double truth = true_cost(*spec, s);
        if (!std::isnan(truth)) {
          EXPECT_LE(hs, truth + 1e-9) << "admissibility";
        }
      }
      s = spec->task().apply(s, acts[rng() % acts.size()]);
    }
  }
}

// h_FF: at least h_max (a relaxed plan reaches every goal atom, so it costs at
// least the dearest one), 0 at goals, and A* with it finds valid plans no
// cheaper than optimal. On the workshop (STRIPS, goals needing several
// fetches) it counts every fetch where h_max sees only the longest.
TEST(HFF, BoundsAndPlansOnTheWorkshop) {
  auto ds = data::Dataset::load(CLIPS_SOURCE_DIR "/data/datasets/workshop");
  std::mt19937 rng(11);
  int larger = 0;
  for (const char* problem : {"1", "3"}) {
    auto task = ds.task(problem);
    for (const char* product : {"table", "birdhouse", "frame"}) {
      if (!task->find_object(product)) continue;
      auto spec = std::make_shared<model::Specification>(task, std::string("(made ") + product + ")",
                                                         model::unit_profile());
      heuristics::FFHeuristic ff;
      heuristics::HMaxHeuristic hmax;
      pddl::State s = task->initial_state();
      ff.prepare(*spec, s);
      hmax.prepare(*spec, s);
      for (int step = 0; step < 12 && !spec->is_goal(s); ++step) {
        const double hf = ff.estimate(s.data()), hm = hmax.estimate(s.data());
        EXPECT_GE(hf + 1e-9, hm) << problem << " " << product << " step " << step;
        if (hf > hm + 1e-9) ++larger;
        auto acts = task->applicable_actions(s);
        ASSERT_FALSE(acts.empty());
        s = task->apply(s, acts[rng() % acts.size()]);
      }
      heuristics::HMaxHeuristic optimal;
      auto best = search::plan(*spec, optimal, task->initial_state());
      auto r = search::plan(*spec, ff, task->initial_state());
      ASSERT_EQ(r.status, search::SearchStatus::Success) << problem << " " << product;
      ASSERT_EQ(best.status, search::SearchStatus::Success) << problem << " " << product;
      auto sim = pddl::simulate(*task, task->initial_state(), r.plan);
      EXPECT_TRUE(spec->is_goal(sim.states.back()));
      EXPECT_GE(r.cost + 1e-9, best.cost);
      EXPECT_LT(r.expanded, best.expanded) << "h_FF should guide A* better than h_max here";
      EXPECT_EQ(ff.estimate(sim.states.back().data()), 0);
    }
  }
  EXPECT_GT(larger, 0) << "h_FF should see more than the dearest subgoal somewhere";
}

TEST(Rtaa, PathReuseMakesLaterRefinementsCheaper) {
  auto ds = data::Dataset::load(paths::examples_dir() + "/doors-keys-gems");
  auto spec = spec_for(ds, "e2", 2, 3);
  auto h = std::make_shared<heuristics::HMaxHeuristic>();
  search::Policy pol(spec, h);
  pddl::State s = spec->task().initial_state();
  auto first = pol.refine(s, search::SearchOptions{});
  auto a = pol.best_action(s);
  ASSERT_TRUE(a);
  pddl::State next = spec->task().apply(s, *a);
  auto reused = pol.refine(next, search::SearchOptions{});
  search::Policy fresh(spec, h);
  auto from_scratch = fresh.refine(next, search::SearchOptions{});
  EXPECT_GT(first.expanded, 0u);
  EXPECT_GT(pol.tree_size(), 0u);
  // Searches stop at states on the stored goal path and start from learned values.
  EXPECT_LT(reused.expanded, from_scratch.expanded);
  EXPECT_NEAR(pol.value(next), fresh.value(next), 1e-9);
  // The rollout follows the stored path to the goal.
  auto plan = pol.rollout(next, 200);
  auto sim = pddl::simulate(spec->task(), next, plan);
  EXPECT_TRUE(spec->is_goal(sim.states.back()));
}
