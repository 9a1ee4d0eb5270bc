#include "search/state_registry_test.hpp"

TEST(AStarWorkspace, ReusedWorkspaceMatchesFreshSearches) {
  auto ds = data::Dataset::load(paths::examples_dir() + "/doors-keys-gems");
  heuristics::HMaxHeuristic h;
  search::SearchWorkspace ws;
  for (const char* p : {"e1", "e2"})
    for (int g = 1; g <= 4; ++g)
      for (size_t budget : {size_t{5}, size_t{1} << 20}) {
        model::Specification spec(ds.task(p), "(has human gem" + std::to_string(g) + ")", fixtures::dkg_profile(1));
        search::SearchOptions o;
        o.max_nodes = budget;
        auto fresh = search::plan(spec, h, spec.task().initial_state(), o);
        const auto& again = search::astar(spec, h, spec.task().initial_state(), o, ws);
        EXPECT_EQ(again.status, fresh.status);
        EXPECT_EQ(again.plan, fresh.plan);
        EXPECT_EQ(again.cost, fresh.cost);
        EXPECT_EQ(again.expanded, fresh.expanded);
        EXPECT_EQ(again.generated, fresh.generated);
        EXPECT_EQ(again.terminal, fresh.terminal);
        ASSERT_EQ(again.registry->size(), fresh.registry->size());
        ASSERT_EQ(again.nodes.size(), fresh.nodes.size());
        for (size_t i = 0; i < fresh.nodes.size(); ++i) {
          EXPECT_EQ(again.nodes[i].g, fresh.nodes[i].g);
          EXPECT_EQ(again.nodes[i].h, fresh.nodes[i].h);
          EXPECT_EQ(again.nodes[i].parent, fresh.nodes[i].parent);
        }
      }
}
