#include "search/strips_export_test.hpp"

// Every dataset problem and gem; the profile rotates with the gem so each
// problem still sees all four profiles while the running time stays bounded
// (all 16 combinations take minutes with the generic h_max). Searches above
// the expansion budget are skipped and counted.
TEST(StripsExport, SameOptimalCostOnTheDataset) {
  const std::string dir = CLIPS_SOURCE_DIR "/../shared/dataset/doors-keys-gems";
  if (!std::filesystem::exists(dir + "/domain.pddl")) GTEST_SKIP() << "shared dataset not present";
  auto ds = data::Dataset::load(dir);
  std::set<std::string> problems;
  for (auto& pl : ds.plans()) problems.insert(pl.problem_id);
  int compared = 0, skipped = 0, pi = 0;
  for (auto& p : problems) {
    auto task = ds.task(p);
    for (int g = 1; g <= 4; ++g) {
      int c = 1 + (g + pi) % 4;
      if (check_equivalent(task, task->initial_state(), g, c, "dataset " + p, 400000)) ++compared;
      else ++skipped;
    }
    ++pi;
  }
  std::printf("compared %d dataset (problem, gem, profile) triples; %d exceeded the expansion budget\n", compared,
              skipped);
  EXPECT_GE(compared, 3 * (compared + skipped) / 4);
}
