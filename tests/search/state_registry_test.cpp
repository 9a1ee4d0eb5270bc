#include "search/state_registry_test.hpp"

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
