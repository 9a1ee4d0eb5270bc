#include "engine/front_ends_test.hpp"

namespace front_ends_test {
TEST(FrontEnds, EveryRepoDatasetIsHeardAlikeByEveryFrontEnd) {
  // One plan with an instruction per dataset: posteriors equal, not close.
  for (const std::string name : {"garden", "hospital", "kitchen", "lab", "warehouse", "workshop"}) {
    const std::string dir = clips::paths::source_dir() + "/data/datasets/" + name;
    const auto ds = clips::data::Dataset::load(dir);
    const clips::data::PlanRecord* plan = nullptr;
    for (const auto& p : ds.plans())
      if (!plan && !p.observed.utterances.empty()) plan = &p;
    ASSERT_NE(plan, nullptr) << name;
    const Checkpoints cli = cli_checkpoints(dir, plan->id);
    ASSERT_EQ(cli.size(), plan->observed.actions.size() + 1) << name;
    EXPECT_EQ(session_checkpoints(dir, *plan), cli) << name << " " << plan->id << ": C++ session";
    EXPECT_EQ(server_checkpoints(dir, *plan), cli) << name << " " << plan->id << ": server";
    Checkpoints run_plan;
    EXPECT_EQ(python_checkpoints(dir, *plan, &run_plan), cli) << name << " " << plan->id << ": Python session";
    EXPECT_EQ(run_plan, cli) << name << " " << plan->id << ": Python run_plan";
  }
}

}  // namespace front_ends_test
