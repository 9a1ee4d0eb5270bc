// StateRegistry / StateMap: ids in insertion order across table growth and
// clear(), lookups with precomputed hashes, and A* with a reused workspace
// giving the same result as a fresh search.
#include <gtest/gtest.h>

#include <array>
#include <random>

#include "data/dataset.hpp"
#include "heuristics/basic.hpp"
#include "search/astar.hpp"
#include "search/state_registry.hpp"
#include "test_paths.hpp"
#include "dkg_profiles.hpp"

using namespace clips;

TEST(StateRegistry, IdsFollowInsertionOrderThroughGrowthAndClear) {
  search::StateRegistry reg(3);
  std::mt19937_64 rng(7);
  std::vector<std::array<uint64_t, 3>> states(5000);
  for (auto& s : states) s = {rng(), rng() & 0xff, rng() % 3};  // words that collide often
  for (int round = 0; round < 2; ++round) {
    std::vector<int> ids;
    for (auto& s : states) {
      bool added = false;
      int id = reg.insert(s.data(), &added);
      if (added) {
        EXPECT_EQ(id, reg.size() - 1);
      }
      ids.push_back(id);
    }
    for (size_t i = 0; i < states.size(); ++i) {
      EXPECT_EQ(reg.find(states[i].data()), ids[i]);
      EXPECT_EQ(reg.find_hashed(states[i].data(), reg.hash(states[i].data())), ids[i]);
      EXPECT_TRUE(std::equal(states[i].begin(), states[i].end(), reg.get(ids[i])));
    }
    std::array<uint64_t, 3> absent{1, 2, 3};
    EXPECT_EQ(reg.find(absent.data()), -1);
    reg.clear();
    EXPECT_EQ(reg.size(), 0);
    EXPECT_EQ(reg.find(states[0].data()), -1);
  }
}

TEST(StateMap, InsertHashedReportsNewStates) {
  search::StateMap<int> m(2);
  uint64_t a[2] = {1, 2}, b[2] = {2, 1};
  bool added = false;
  m.insert_hashed(a, m.hash(a), &added) = 5;
  EXPECT_TRUE(added);
  EXPECT_EQ(m.insert_hashed(a, m.hash(a), &added), 5);
  EXPECT_FALSE(added);
  EXPECT_EQ(m.find(b), nullptr);
  m[b] = 7;
  EXPECT_EQ(*m.find_hashed(b, m.hash(b)), 7);
  EXPECT_EQ(m.size(), 2);
}

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
