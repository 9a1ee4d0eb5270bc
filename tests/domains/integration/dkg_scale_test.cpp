#include "domains/dkg_scale_test.hpp"

namespace clips::domains::dkg {
namespace dkg_scale_test {
TEST(DkgScale, FortyByFortyMapWithSixtyFourGems) {
  BigMap big;
  const pddl::Task& t = *big.task;
  const auto map = DkgMapAnalysis::build(big.task, t.initial_state());
  ASSERT_EQ(map->num_objects(), 70);  // 2 agents, 2 keys + 64 gems, 2 doors
  ASSERT_EQ(map->width(), 40);
  // Items sort by name (gem1, gem10, ..., gem9, key1, key2), so gem9, the
  // keys and the doors have object indices of 64 or more.
  const int g64 = map->index_of(*t.find_object("gem9"));
  const int door2 = map->index_of(*t.find_object("door2"));
  EXPECT_EQ(g64, 65);
  EXPECT_EQ(door2, 69);
  const auto view = map->read(t.initial_state());
  EXPECT_TRUE(map->locked(view, door2));  // door bits live in the 128-bit locked mask too

  model::Specification spec(big.task, "(has human gem9)", fixtures::dkg_profile(3));
  DkgMstHeuristic mst(map);
  mst.prepare(spec, t.initial_state());
  EXPECT_TRUE(mst.goal_items() == mask_bit(g64));
  EXPECT_EQ(mask_popcount(mst.goal_items()), 1);
  // Some door stands before every gem, so the pruning keeps a door and its key.
  EXPECT_GE(mask_popcount(mst.necessary_doors()), 1);
  EXPECT_GE(mask_popcount(mst.necessary_keys()), 1);
  const double h_mst = mst.estimate(t.initial_state());
  EXPECT_GT(h_mst, 0);
  EXPECT_LT(h_mst, 1e6);

  // A plan to the gem exists: A* guided by the MST heuristic (the one
  // inference and the generator's reachability check use) finds one, and the
  // admissible bound stays below its cost.
  DkgMstHeuristic guide(map);
  search::SearchOptions so;
  so.max_nodes = size_t{1} << 20;
  const auto r = search::plan(spec, guide, t.initial_state(), so);
  ASSERT_EQ(r.status, search::SearchStatus::Success);
  EXPECT_GT(r.plan.size(), 2u);
  DkgDistanceHeuristic dist(map);
  dist.prepare(spec, t.initial_state());
  const double h_dist = dist.estimate(t.initial_state());
  EXPECT_GT(h_dist, 0);
  EXPECT_LE(h_dist, r.cost + 1e-9);
}

}  // namespace dkg_scale_test

}  // namespace clips::domains::dkg
