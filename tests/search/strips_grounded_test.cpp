#include "search/strips_grounded_test.hpp"

// Exhaustively (blind A*) from the start and from states along random walks.
TEST(StripsGrounded, DisjunctionsConditionalEffectsAndNegativeGoals) {
  auto task = read_task(kSwitchDomain, kSwitchProblem);
  const std::vector<std::string> goals = {"(and (on b) (on c) (not (broken a)))", "(or (broken c) (not (on a)))",
                                          "(and (not (power)) (on a) (on b))"};
  pddl::State s = task->initial_state();
  int solved = 0;
  for (int step = 0; step < 6; ++step) {
    for (const auto& g : goals) {
      SCOPED_TRACE(g + " step " + std::to_string(step));
      auto r = solve_both(task, s, g, model::task_costs_profile(), /*lmcut=*/false);
      solved += r.original.status == search::SearchStatus::Success;
      // LM-cut is admissible on the export too (and the original task has
      // conditional effects, which it reads as plain adds).
      auto l = solve_both(task, s, g, model::task_costs_profile(), /*lmcut=*/true);
      EXPECT_EQ(l.original.cost, r.original.cost);
    }
    auto acts = task->applicable_actions(s);
    ASSERT_FALSE(acts.empty());
    s = task->apply(s, acts[static_cast<size_t>(step * 7 + 3) % acts.size()]);
  }
  EXPECT_GE(solved, 12);
}

// Numeric tasks are refused with a message naming the way out.
TEST(StripsGrounded, NumericTasksAreRefused) {
  auto ds = data::Dataset::load(paths::examples_dir() + "/doors-keys-gems");
  auto task = ds.task("e1");
  try {
    domains::export_grounded_strips(*task, task->initial_state(), "(has human gem1)", model::unit_profile());
    FAIL() << "no error";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("numeric"), std::string::npos) << e.what();
  }
}
