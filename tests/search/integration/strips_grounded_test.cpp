#include "search/strips_grounded_test.hpp"

// Every problem and candidate goal of the workshop, unit costs and a 0.6
// wait (scaled by 5), from the initial state and from where each plan's
// observed part ends: the same optimal cost, and the time ratio of solving
// the export to solving the task (both A* with LM-cut; on the export LM-cut
// has no turn structure to read, since its actions name no agent).
TEST(StripsGrounded, SameOptimalCostsAsClipsPlanOnTheWorkshop) {
  const fs::path dir = fs::path(paths::source_dir()) / "data" / "datasets" / "workshop";
  auto ds = data::Dataset::load(dir.string());
  model::CostProfile cheap_wait = model::unit_profile();
  cheap_wait.name = "wait-0.6";
  cheap_wait.costs[{"human", "wait"}] = 0.6;
  cheap_wait.costs[{"robot", "wait"}] = 0.6;
  int checked = 0;
  double t_task = 0, t_export = 0;
  for (auto& set : fs::directory_iterator(dir / "goals" / "sets")) {
    const std::string problem = set.path().stem().string();
    auto task = ds.task(problem);
    std::vector<pddl::State> starts = {task->initial_state()};
    for (const auto& p : ds.plans())
      if (p.problem_id == problem) starts.push_back(pddl::simulate(*task, task->initial_state(), p.observed).states.back());
    std::ifstream in(set.path());
    for (std::string label; in >> label;) {
      std::ifstream def(dir / "goals" / "definitions" / (label + ".pddl"));
      const std::string goal((std::istreambuf_iterator<char>(def)), {});
      for (size_t k = 0; k < starts.size(); ++k)
        for (const auto& profile : {model::unit_profile(), cheap_wait}) {
          if (k > 0 && profile.name != "unit") continue;  // mid-plan states: unit costs only
          SCOPED_TRACE("problem " + problem + " goal " + label + " start " + std::to_string(k) + " " + profile.name);
          auto r = solve_both(task, starts[k], goal, profile, /*lmcut=*/true);
          ASSERT_EQ(r.original.status, search::SearchStatus::Success);
          t_task += r.original.seconds;
          t_export += r.exported.seconds;
          ++checked;
        }
    }
  }
  std::cout << checked << " workshop tasks: A*(LM-cut) " << t_task << " s on the tasks, " << t_export
            << " s on their exports (ratio " << t_export / t_task << ")\n";
  EXPECT_GE(checked, 100);
}
