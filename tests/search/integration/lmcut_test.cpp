#include "search/lmcut_test.hpp"

// Admissibility: on states along random walks (with and without the robot
// frozen, on either agent's turn) LM-cut never exceeds the optimal cost, on
// the workshop, the storeroom profiling domain and the Doors-Keys-Gems
// examples (numeric grid positions, the paper's costs with a 0.6 wait).
TEST(LmCut, AdmissibleOnRandomWalks) {
  struct Case {
    std::string dir, problem;
    std::vector<std::string> goals;
    int profile;  // 0: unit; else the mDKG profile
  };
  std::vector<Case> cases = {
      {workshop_dir(), "1", {}, 0},
      {workshop_dir(), "3", {}, 0},
      {workshop_dir(), "8", {}, 0},
      {paths::source_dir() + "/bench/data/storeroom", "4", {}, 0},
      {paths::examples_dir() + "/doors-keys-gems", "e1", {"(has human gem1)", "(has human gem3)"}, 1},
      {paths::examples_dir() + "/doors-keys-gems", "e1", {"(has human gem2)"}, 4},
  };
  std::mt19937 rng(5);
  int checked = 0, exact = 0;
  for (const Case& c : cases) {
    auto ds = data::Dataset::load(c.dir);
    auto task = ds.task(c.problem);
    std::vector<std::string> goals = c.goals;
    if (goals.empty())
      for (const auto& label : goal_set(c.dir, c.problem)) goals.push_back(goal_text(c.dir, label));
    const model::CostProfile profile = c.profile ? fixtures::dkg_profile(c.profile) : model::unit_profile();
    for (const auto& g : goals) {
      model::Specification spec(task, g, profile);
      heuristics::LmCutHeuristic h;
      h.prepare(spec, task->initial_state());
      pddl::State s = task->initial_state();
      for (int step = 0; step < 16; ++step) {
        if (step % 4 == 0) {
          for (bool freeze : {false, true}) {
            const pddl::State t = freeze ? model::freeze(*task, s, "robot") : s;
            const double truth = optimal_cost(spec, t, 20000);
            if (std::isnan(truth)) continue;
            const double est = h.estimate(t.data());
            EXPECT_LE(est, truth + 1e-9) << c.dir << " " << c.problem << " " << g << " step " << step
                                         << (freeze ? " frozen" : "");
            if (truth < model::kInf && std::abs(est - truth) < 1e-9) ++exact;
            ++checked;
          }
        }
        auto acts = task->applicable_actions(s);
        if (acts.empty() || spec.is_goal(s)) break;
        s = task->apply(s, acts[rng() % acts.size()]);
      }
    }
  }
  std::cout << "LM-cut checked against h* on " << checked << " states, exact on " << exact << "\n";
  EXPECT_GE(checked, 100);
}

// A* with LM-cut finds the same optimal cost as A* with h_max for every
// candidate goal of every workshop problem, from the initial state, and
// expands fewer states.
TEST(LmCut, SameOptimalCostsAsHMaxOnTheWorkshop) {
  const std::string dir = workshop_dir();
  auto ds = data::Dataset::load(dir);
  size_t goals = 0, exp_lmcut = 0, exp_hmax = 0;
  double t_lmcut = 0, t_hmax = 0;
  for (auto& set : fs::directory_iterator(fs::path(dir) / "goals" / "sets")) {
    const std::string problem = set.path().stem().string();
    auto task = ds.task(problem);
    for (const auto& label : goal_set(dir, problem)) {
      SCOPED_TRACE("problem " + problem + ", goal " + label);
      model::Specification spec(task, goal_text(dir, label), model::unit_profile());
      heuristics::HMaxHeuristic hmax;
      heuristics::LmCutHeuristic lm;
      auto a = search::plan(spec, hmax, task->initial_state());
      auto b = search::plan(spec, lm, task->initial_state());
      ASSERT_EQ(a.status, search::SearchStatus::Success);
      ASSERT_EQ(b.status, search::SearchStatus::Success);
      EXPECT_DOUBLE_EQ(a.cost, b.cost);
      EXPECT_TRUE(spec.is_goal(pddl::simulate(*task, task->initial_state(), b.plan).states.back()));
      exp_hmax += a.expanded;
      exp_lmcut += b.expanded;
      t_hmax += a.seconds;
      t_lmcut += b.seconds;
      ++goals;
    }
  }
  std::cout << goals << " goals: h_max " << exp_hmax << " expansions (" << t_hmax << " s), LM-cut " << exp_lmcut
            << " (" << t_lmcut << " s)\n";
  EXPECT_GE(goals, 30u);
  EXPECT_LT(exp_lmcut, exp_hmax);
}
