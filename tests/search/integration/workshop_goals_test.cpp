// Every candidate goal of every problem of the workshop dataset
// (data/datasets/workshop) is solvable from the problem's initial state, and
// the plan found, replayed, reaches the goal. The robot is frozen (it can only
// wait), which keeps the search small: a goal the human reaches alone is
// solvable, and the joint optimal plans are `clips plan`'s job (its run over
// all goals is in the dataset's README).
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>

#include "data/dataset.hpp"
#include "heuristics/basic.hpp"
#include "search/astar.hpp"
#include "test_paths.hpp"

using namespace clips;

namespace {

namespace fs = std::filesystem;

TEST(WorkshopGoals, EveryCandidateGoalIsSolvableFromTheInitialState) {
  const fs::path dir = fs::path(paths::source_dir()) / "data" / "datasets" / "workshop";
  auto ds = data::Dataset::load(dir.string());
  int goals = 0;
  for (auto& set : fs::directory_iterator(dir / "goals" / "sets")) {
    const std::string problem = set.path().stem().string();
    auto task = ds.task(problem);
    std::ifstream in(set.path());
    std::string label;
    while (in >> label) {
      SCOPED_TRACE("problem " + problem + ", goal " + label);
      const fs::path def = dir / "goals" / "definitions" / (label + ".pddl");
      std::ifstream din(def);
      const std::string text((std::istreambuf_iterator<char>(din)), {});
      model::Specification spec(task, text, model::unit_profile(), def.string());
      heuristics::HMaxHeuristic h;
      search::SearchOptions opts;
      opts.max_nodes = 20000;  // each goal needs fewer than 8,000 expansions
      const pddl::State start = model::freeze(*task, task->initial_state(), "robot");
      auto r = search::plan(spec, h, start, opts);
      ASSERT_EQ(r.status, search::SearchStatus::Success);
      auto sim = pddl::simulate(*task, start, r.plan);
      EXPECT_TRUE(spec.is_goal(sim.states.back().data()));
      ++goals;
    }
  }
  EXPECT_GE(goals, 24);
}

}  // namespace
