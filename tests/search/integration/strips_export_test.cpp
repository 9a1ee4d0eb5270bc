#include "search/strips_export_test.hpp"

TEST(StripsExport, FrozenRobotMayOnlyWaitOrHandOver) {
  auto ds = examples();
  for (const char* p : {"e1", "e2"}) {
    auto task = ds.task(p);
    auto frozen = model::freeze(*task, task->initial_state(), "robot");
    auto ex = domains::dkg::export_strips(*task, frozen, "(has human gem1)", fixtures::dkg_profile(1));
    EXPECT_EQ(ex.problem.find("(unfrozen robot)"), std::string::npos);
    EXPECT_NE(ex.problem.find("(unfrozen human)"), std::string::npos);
    for (int g = 1; g <= 4; ++g)
      for (int c : {1, 4}) check_equivalent(task, frozen, g, c, std::string(p) + " frozen robot");
  }
}
