// Maps beyond 64 objects: the 128-bit object masks of the mDKG heuristics
// (dkg_mask.hpp) and a generated 40x40 map with 64 gems, on which the map
// analysis builds, both heuristics evaluate and A* finds a plan to a gem whose
// object index is 64 or more.
#include <gtest/gtest.h>

#include <vector>

#include "domains/dkg_generate.hpp"
#include "domains/dkg_heuristic.hpp"
#include "domains/dkg_mask.hpp"
#include "domains/pack.hpp"
#include "model/spec.hpp"
#include "pddl/parser.hpp"
#include "search/astar.hpp"
#include "test_paths.hpp"
#include "util/rng.hpp"
#include "dkg_profiles.hpp"

namespace clips::domains {
namespace {

TEST(ObjMask, BitsAboveSixtyFour) {
  static_assert(kObjMaskBits == 128);
  const ObjMask m = mask_bit(0) | mask_bit(63) | mask_bit(64) | mask_bit(100) | mask_bit(127);
  EXPECT_TRUE(mask_has(m, 0) && mask_has(m, 63) && mask_has(m, 64) && mask_has(m, 100) && mask_has(m, 127));
  EXPECT_FALSE(mask_has(m, 1) || mask_has(m, 62) || mask_has(m, 65) || mask_has(m, 126));
  EXPECT_EQ(mask_popcount(m), 5);
  EXPECT_EQ(mask_ctz(m), 0);
  EXPECT_EQ(mask_ctz(mask_bit(64)), 64);
  EXPECT_EQ(mask_ctz(mask_bit(127)), 127);
  EXPECT_EQ(mask_ctz(mask_bit(64) | mask_bit(90)), 64);
  std::vector<int> seen;
  mask_for_each(m, [&](int i) { seen.push_back(i); });
  EXPECT_EQ(seen, (std::vector<int>{0, 63, 64, 100, 127}));
  // The low word alone is the old 64-bit mask.
  EXPECT_EQ(static_cast<uint64_t>(mask_bit(5) | mask_bit(70)), uint64_t{1} << 5);
  EXPECT_EQ(mask_popcount(~ObjMask{0}), 128);
}

struct BigMap {
  std::shared_ptr<const pddl::Task> task;
  BigMap() {
    GenerateParams p;
    p.width = p.height = 40;
    p.counts = {{"gem", 64}, {"key", 2}, {"door", 2}};
    p.problem_name = "big";
    util::Rng rng(11);
    std::optional<GeneratedProblem> g;
    for (int i = 0; i < 200 && !g; ++i) g = generate_dkg_problem(p, rng);
    if (!g) throw std::runtime_error("no 40x40 map in 200 draws");
    auto d = std::make_shared<pddl::Domain>(
        pddl::load_domain(paths::source_dir() + "/data/domains/doors-keys-gems/domain.pddl"));
    auto pr = std::make_shared<pddl::Problem>(pddl::parse_problem(*d, g->pddl, "big.pddl"));
    auto pack = builtin_pack("doors-keys-gems");
    task = std::make_shared<const pddl::Task>(d, pr, pack->spec().grounding);
  }
};

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

}  // namespace
}  // namespace clips::domains
