#include "search/astar_test.hpp"

TEST(AStar, DefaultHeuristicMatchesUniformCostSearchOnTheDataset) {
  if (!paths::have_shared_dataset()) GTEST_SKIP() << "shared dataset not present";
  auto ds = data::Dataset::load(paths::dkg_dataset());
  std::set<std::string> problems;
  for (auto& p : ds.plans()) problems.insert(p.problem_id);
  int compared = 0, skipped = 0;
  for (auto& p : problems)
    for (int g = 1; g <= 4; ++g)
      for (int c = 1; c <= 4; ++c) {
        auto spec = spec_for(ds, p, g, c);
        auto h = ds.pack().make_heuristic(ds.pack().default_admissible_heuristic(), spec->task());
        double ucs = true_cost(*spec, spec->task().initial_state(), 1u << 15);
        if (std::isnan(ucs)) {
          ++skipped;
          continue;
        }
        ++compared;
        auto r = search::plan(*spec, *h, spec->task().initial_state());
        if (ucs == model::kInf) {
          EXPECT_EQ(r.status, search::SearchStatus::Failure);
        } else {
          ASSERT_EQ(r.status, search::SearchStatus::Success) << p << " gem" << g << " C" << c;
          EXPECT_NEAR(r.cost, ucs, 1e-9) << p << " gem" << g << " C" << c;
        }
      }
  std::cout << "compared " << compared << " tasks with uniform-cost search; " << skipped
            << " exceeded the UCS budget\n";
  EXPECT_GT(compared, 0);
}
