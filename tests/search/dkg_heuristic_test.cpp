#include "search/dkg_heuristic_test.hpp"

TEST(DkgMap, RoomsGraphAndDistancesOfMapA) {
  Hand h = make_map_a();
  auto m = DkgMapAnalysis::build(h.task, h.task->initial_state());
  // Column-major labelling: the left block (x 1-2) is room 1, the right block
  // (x 4-5) room 2; door1 gets 2 + 1 = 3; walls 0.
  EXPECT_EQ(m->num_rooms(), 2);
  EXPECT_EQ(m->label(m->cell(1, 1)), 1);
  EXPECT_EQ(m->label(m->cell(2, 3)), 1);
  EXPECT_EQ(m->label(m->cell(5, 1)), 2);
  EXPECT_EQ(m->label(m->cell(3, 2)), 3);
  EXPECT_EQ(m->label(m->cell(3, 1)), 0);
  EXPECT_EQ(m->room_neighbors(3), (std::vector<int>{1, 2}));
  EXPECT_EQ(m->room_neighbors(1), (std::vector<int>{3}));
  EXPECT_TRUE(m->room_adjacent(1, 3));
  EXPECT_FALSE(m->room_adjacent(1, 2));
  // Objects: human, robot, gem1, key1, door1.
  EXPECT_EQ(m->name(0), "human");
  EXPECT_EQ(m->name(1), "robot");
  EXPECT_EQ(m->name(2), "gem1");
  EXPECT_EQ(m->name(3), "key1");
  EXPECT_EQ(m->name(4), "door1");
  EXPECT_EQ(m->unlockers(4), (std::vector<int>{3}));
  // Doors are passable for distances: (1,2) -> (5,2) is 4 steps.
  EXPECT_EQ(m->dist(m->cell(1, 2), m->cell(5, 2)), 4);
  EXPECT_EQ(m->dist(m->cell(1, 1), m->cell(3, 2)), 3);
  EXPECT_EQ(m->dist(m->cell(1, 1), m->cell(3, 1)), DkgMapAnalysis::kNoPath);  // a wall
}

TEST(DkgMap, RecursiveKeepsTheReferenceQuirkOnMapD) {
  Hand h = make_map_d();
  auto m = DkgMapAnalysis::build(h.task, h.task->initial_state());
  // Rooms (column-major): 1 = {(1,1),(2,1)}, 2 = row 3, 3 = {(3,5)}, 4 = {(4,1),(5,1)};
  // doors: door1 5, door2 6, door3 7, door4 8.
  ASSERT_EQ(m->num_rooms(), 4);
  EXPECT_EQ(m->label(m->cell(4, 1)), 4);
  EXPECT_EQ(m->label(m->cell(3, 5)), 3);
  EXPECT_EQ(m->room_neighbors(1), (std::vector<int>{5, 6}));
  EXPECT_EQ(m->room_neighbors(2), (std::vector<int>{5, 7, 8}));
  EXPECT_EQ(m->room_neighbors(4), (std::vector<int>{6, 8}));
  auto I = [&](const char* n) { return h.idx(*m, n); };
  const int k1 = I("key1"), k2 = I("key2"), k3 = I("key3"), k4 = I("key4");
  const int d1 = I("door1"), d2 = I("door2"), d3 = I("door3"), d4 = I("door4");
  const int human = I("human"), gem = I("gem1");
  auto v = m->read(h.task->initial_state());

  // PATHSETS(1, 4): paths 1-6-4 (door2) then 1-5-2-8-4 (door1, door4).
  KeyDoorSets p = m->pathsets(1, 4);
  ASSERT_EQ(p.size(), 2u);
  EXPECT_EQ(p[0], (KeyDoorSet{{k2}, {d2}}));
  EXPECT_EQ(p[1], (KeyDoorSet{{k1, k4}, {d1, d4}}));

  std::vector<int> targets{gem, human};
  KeyDoorSets n = m->necessary(v, human, targets);
  EXPECT_EQ(n, p);

  // RECURSIVE: set 0 needs key2, which lies behind door3 (via door1: key1 +
  // key3; or via door2, door4, door3). Set 1 needs nothing (both doors are
  // unlocked) and, coming after set 0, is dropped — the reference's quirk.
  // Iteration 2 merges the two routes to key2; iteration 3 changes nothing.
  KeyDoorSets r = m->recursive(v, human, targets);
  ASSERT_EQ(r.size(), 4u);
  EXPECT_EQ(r[0], (KeyDoorSet{{k2, k1, k3}, {d2, d1, d3}}));
  EXPECT_EQ(r[1], (KeyDoorSet{{k2, k1, k3, k4}, {d2, d1, d3, d4}}));
  EXPECT_EQ(r[2], (KeyDoorSet{{k2, k4, k3, k1}, {d2, d4, d3, d1}}));
  EXPECT_EQ(r[3], (KeyDoorSet{{k2, k4, k3}, {d2, d4, d3}}));
  for (auto& kd : r) EXPECT_NE(kd, (KeyDoorSet{{k1, k4}, {d1, d4}}));
}

TEST(DkgMap, PathsetsNeedDistinctUnlockers) {
  // Map B with one red key: the only route crosses two red doors, so no
  // assignment of distinct keys exists and NECESSARY is empty.
  Hand one = make_map_b(false);
  auto m = DkgMapAnalysis::build(one.task, one.task->initial_state());
  EXPECT_TRUE(m->pathsets(1, 3).empty());
  // With two red keys both assignments appear, first door's key fastest:
  // (key2, key1) before (key1, key2) since key1 < key2 in the unlocker list.
  Hand two = make_map_b(true);
  auto m2 = DkgMapAnalysis::build(two.task, two.task->initial_state());
  auto I = [&](const char* n) { return two.idx(*m2, n); };
  KeyDoorSets p = m2->pathsets(1, 3);
  ASSERT_EQ(p.size(), 2u);
  EXPECT_EQ(p[0], (KeyDoorSet{{I("key2"), I("key1")}, {I("door1"), I("door2")}}));
  EXPECT_EQ(p[1], (KeyDoorSet{{I("key1"), I("key2")}, {I("door1"), I("door2")}}));
}

TEST(DkgMstHeuristic, MapAInitialState) {
  Hand h = make_map_a();
  // C1: move 1, wait 0.6, pickup 1 (robot), unlock 1. S = [([key1],[door1])].
  // Pendants: key1 1, gem1 1, door1 max(0, 1-1) = 0.
  // Edges (x1.6): human-key1 1 -> 1.6, human-door1 2 -> 3.2, key1-door1 3 ->
  // 4.8, door1-gem1 2 -> 3.2; human-gem1 not admitted (rooms 1 and 2).
  // MST 1.6 + 3.2 + 3.2 = 8.0, + 2 = 10.0 (the robot only adds >= 1).
  // The human moves next: 10.0 - 0.6 = 9.4.
  EXPECT_NEAR(mst(h, "(has human gem1)", h.task->initial_state()), 9.4, kEps);
  // C4 raises unlock_min to 2: the door pendant becomes 2 - 1 = 1.
  EXPECT_NEAR(mst(h, "(has human gem1)", h.task->initial_state(), 4), 10.4, kEps);
}

TEST(DkgMstHeuristic, HeldKeyCostsNoPickupAndUsedKeyIsNotNeeded) {
  Hand h = make_map_a();
  // The human holds key1 at (1,1): key1 sits at its holder, pendant 0.
  // human-key1 0, human-door1 3 -> 4.8, door1-gem1 3.2: 8.0 + gem 1 = 9.0,
  // minus one wait: 8.4.
  State held = h.run({"(up human)", "(wait robot)", "(pickup human key1)", "(wait robot)"});
  EXPECT_NEAR(mst(h, "(has human gem1)", held), 8.4, kEps);
  // After unlocking from (2,2): key1 is used, door1 unlocked, so key1 leaves
  // the MST. human-door1 1.6 + door1-gem1 3.2 + gem 1 = 5.8; the robot moves
  // next, so nothing is subtracted.
  State used = h.run({"(up human)", "(wait robot)", "(pickup human key1)", "(wait robot)", "(down human)",
                      "(wait robot)", "(right human)", "(wait robot)", "(unlock human key1 door1)"});
  EXPECT_NEAR(mst(h, "(has human gem1)", used), 5.8, kEps);
}

TEST(DkgMstHeuristic, UsedKeyStillRequiredIsIsolated) {
  Hand h = make_map_b(true);
  // Initial state: both key sets give the same object set {human, key1,
  // key2, door1, door2, gem1}; pendants 3; MST human-key1 1.6, human-key2
  // 1.6, human-door1 3.2, door1-door2 3.2 (doors sharing room 2), door2-gem1
  // 3.2 = 12.8; 15.8 - 0.6 = 15.2.
  EXPECT_NEAR(mst(h, "(has human gem1)", h.task->initial_state()), 15.2, kEps);
  // key1 used on door1: set ([key2,key1],[door1,door2]) needs the used key1
  // for the locked door2 and gets +inf; set ([key1,key2],..) needs key2:
  // pendants key2 1 + gem 1; MST human-door1 1.6, human-key2 3.2,
  // door1-door2 3.2, door2-gem1 3.2 = 11.2; total 13.2 (robot to move).
  State s = h.run({"(up human)", "(wait robot)", "(pickup human key1)", "(wait robot)", "(down human)",
                   "(wait robot)", "(right human)", "(wait robot)", "(unlock human key1 door1)"});
  EXPECT_NEAR(mst(h, "(has human gem1)", s), 13.2, kEps);
}

TEST(DkgMstHeuristic, UnreachableGoalsAreInfinite) {
  // One red key for two red doors in a row: no key assignment.
  Hand one = make_map_b(false);
  EXPECT_EQ(mst(one, "(has human gem1)", one.task->initial_state()), model::kInf);
  // A gem walled off completely.
  Hand boxed({"...W.", "...W.", "...W."},
             {{"human", "human", "", 1, 1}, {"robot", "robot", "", 2, 2}, {"gem1", "gem", "red", 5, 2}});
  EXPECT_EQ(mst(boxed, "(has human gem1)", boxed.task->initial_state()), model::kInf);
}

TEST(DkgMstHeuristic, MapCCorridorAndDisjunctions) {
  Hand h = make_map_c();
  // S = [([key1,key2],[door1,door2])] (RECURSIVE adds nothing new).
  // Pendants key1 1, key2 1, gem1 1; doors 0. MST: human-key1 1.6,
  // human-door1 1.6, door1-key2 1.6, key2-door2 1.6, door2-gem1 3.2 = 9.6.
  // 12.6 - 0.6 = 12.0.
  State s0 = h.task->initial_state();
  EXPECT_NEAR(mst(h, "(has human gem1)", s0), 12.0, kEps);
  // (has human key1): key1 is in the human's room: 1.6 + 1 - 0.6 = 2.0, and a
  // disjunction takes the cheaper clause.
  EXPECT_NEAR(mst(h, "(has human key1)", s0), 2.0, kEps);
  EXPECT_NEAR(mst(h, "(or (has human gem1) (has human key1))", s0), 2.0, kEps);
  // A conjunction: one clause with both items; pickedup-by is dropped.
  EXPECT_NEAR(mst(h, "(and (has human key1) (pickedup-by human key1))", s0), 2.0, kEps);
  // The robot's goal (the human is active, so no wait is subtracted). Rooms
  // of the 9 x 1 corridor: 1 = x 1-2, 2 = x 4, 3 = x 6-7, 4 = x 9; doors 5-7.
  // From room 3, key2 (room 2) lies behind door2, opened by key2 itself:
  // S = [([key2],[door2])], and RECURSIVE's sub-result for key2 is the same
  // set, so S is unchanged. Objects robot, key2, door2: pendant key2 1;
  // robot-door2 1 -> 1.6, door2-key2 1 -> 1.6; 4.2. The human as helper has
  // no admissible edge (room 1) and gives +inf.
  EXPECT_NEAR(mst(h, "(has robot key2)", s0), 4.2, kEps);
}

TEST(DkgMstHeuristic, SatisfiedGoalIsZero) {
  Hand h = make_map_c();
  State s = h.run({"(left human)", "(wait robot)", "(pickup human key1)"});
  EXPECT_EQ(mst(h, "(has human key1)", s), 0.0);
  EXPECT_EQ(mst(h, "(or (has human gem1) (has human key1))", s), 0.0);
}

TEST(DkgMstHeuristic, PruningKeepsOnlyNecessaryKeysAndDoors) {
  Hand h = make_map_c();
  auto spec = h.spec("(has human gem1)");
  DkgMstHeuristic heur;
  heur.prepare(spec, h.task->initial_state());
  EXPECT_TRUE(heur.prunes());
  const auto& m = *heur.map();
  auto bit = [&](const char* n) { return mask_bit(h.idx(m, n)); };  // ObjMask: no gtest printer
  EXPECT_TRUE(heur.necessary_keys() == (bit("key1") | bit("key2")));
  EXPECT_TRUE(heur.necessary_doors() == (bit("door1") | bit("door2")));
  EXPECT_TRUE(heur.goal_items() == (bit("gem1")));
  auto keep = [&](const std::string& a) {
    auto id = h.task->find_action(a);
    EXPECT_TRUE(id) << a;
    return id && heur.keep(*id);
  };
  EXPECT_TRUE(keep("(pickup human key1)"));
  EXPECT_TRUE(keep("(pickup robot key2)"));
  EXPECT_TRUE(keep("(pickup human gem1)"));
  EXPECT_FALSE(keep("(pickup human key3)"));
  EXPECT_FALSE(keep("(pickup robot key3)"));
  EXPECT_TRUE(keep("(handover robot human key2)"));
  EXPECT_FALSE(keep("(handover robot human key3)"));
  EXPECT_TRUE(keep("(unlock human key1 door1)"));
  EXPECT_TRUE(keep("(unlock robot key2 door2)"));
  EXPECT_FALSE(keep("(unlock human key3 door3)"));  // door3 is not on the way
  EXPECT_TRUE(keep("(up human)"));
  EXPECT_TRUE(keep("(wait robot)"));

  // A key that is itself the goal: the way to key3 (x 9) crosses door1,
  // door2 and door3, so all three keys become necessary and key3, a goal
  // item, may be picked up, handed over and used.
  auto spec3 = h.spec("(has human key3)");
  heur.prepare(spec3, h.task->initial_state());
  EXPECT_TRUE(heur.necessary_keys() == (bit("key1") | bit("key2") | bit("key3")));
  EXPECT_TRUE(heur.necessary_doors() == (bit("door1") | bit("door2") | bit("door3")));
  EXPECT_TRUE(keep("(pickup human key3)"));
  EXPECT_TRUE(keep("(handover robot human key3)"));
  EXPECT_TRUE(keep("(unlock human key3 door3)"));
}

TEST(DkgMstHeuristic, IdleGemsAreNotPickedUpInsideSearches) {
  // Map A with a second gem beside the human: for (has human gem1), taking
  // gem2 (pickup 5, wait 0.6 in profile 1) only costs, so A* skips it; the
  // reference rule and goals that name gem2 keep it.
  Hand h({"..W..", ".....", "..W.."},
         {{"human", "human", "", 1, 2}, {"robot", "robot", "", 1, 3}, {"key1", "key", "red", 1, 1},
          {"door1", "door", "red", 3, 2, true}, {"gem1", "gem", "red", 5, 2}, {"gem2", "gem", "blue", 2, 2}});
  auto keeps = [&](DkgMstHeuristic& heur, const std::string& goal, const std::string& action) {
    auto spec = h.spec(goal);
    heur.prepare(spec, h.task->initial_state());
    auto id = h.task->find_action(action);
    EXPECT_TRUE(id) << action;
    return id && heur.keep(*id);
  };
  DkgMstHeuristic idle, reference(nullptr, 5, ItemPruning::Reference);
  EXPECT_TRUE(dkg_idle_items(*DkgMapAnalysis::build(h.task, h.task->initial_state())) != 0);
  EXPECT_FALSE(keeps(idle, "(has human gem1)", "(pickup human gem2)"));
  EXPECT_TRUE(keeps(idle, "(has human gem1)", "(pickup human gem1)"));
  EXPECT_TRUE(keeps(idle, "(has human gem1)", "(pickup human key1)"));
  EXPECT_TRUE(keeps(reference, "(has human gem1)", "(pickup human gem2)"));
  EXPECT_TRUE(keeps(idle, "(or (has human gem1) (has human gem2))", "(pickup human gem2)"));
  // gem2 named by an atom the clauses drop: kept.
  EXPECT_TRUE(keeps(idle, "(and (has human gem1) (not (offgrid gem2)))", "(pickup human gem2)"));
  // With pickups cheaper than waiting a pickup may be the cheapest way to
  // pass a turn, so it stays.
  model::CostProfile cheap = fixtures::dkg_profile(1);
  for (auto& [key, c] : cheap.costs)
    if (key.second == "pickup") c = 0.1;
  model::Specification spec(h.task, "(has human gem1)", cheap);
  idle.prepare(spec, h.task->initial_state());
  EXPECT_TRUE(idle.keep(*h.task->find_action("(pickup human gem2)")));
  // The values searches learn are unchanged here: RTAA* refinements with both rules agree.
  auto pspec = std::make_shared<const model::Specification>(h.spec("(has human gem1)"));
  search::Policy a(pspec, std::make_shared<DkgMstHeuristic>()),
      b(pspec, std::make_shared<DkgMstHeuristic>(nullptr, 5, ItemPruning::Reference));
  a.refine(h.task->initial_state(), {});
  b.refine(h.task->initial_state(), {});
  EXPECT_EQ(a.value(h.task->initial_state()), b.value(h.task->initial_state()));
}

TEST(DkgMstHeuristic, SharedMapAnalysisAndMemoGiveFreshValues) {
  Hand h = make_map_d();
  auto spec = h.spec("(has human gem1)");
  auto map = DkgMapAnalysis::build(h.task, h.task->initial_state());
  DkgMstHeuristic shared(map);
  shared.prepare(spec, h.task->initial_state());
  EXPECT_EQ(shared.map(), map);
  std::mt19937 rng(7);
  for (int i = 0; i < 300; ++i) {
    State s = random_walk(*h.task, h.task->initial_state(), i % 40, rng);
    DkgMstHeuristic fresh(map);
    fresh.prepare(spec, h.task->initial_state());
    double a = shared.estimate(s), b = fresh.estimate(s);
    if (std::isinf(a) || std::isinf(b)) EXPECT_EQ(a, b);
    else EXPECT_NEAR(a, b, kEps);
  }
}

TEST(DkgMstHeuristic, PropertiesAreDeclaredUnproven) {
  DkgMstHeuristic h;
  EXPECT_FALSE(h.admissible());
  EXPECT_FALSE(h.consistent());
  EXPECT_EQ(h.name(), "dkg-mst");
  DkgDistanceHeuristic d;
  EXPECT_TRUE(d.admissible());
  EXPECT_TRUE(d.consistent());
}

TEST(DkgDistanceHeuristic, HandValuesOnMapC) {
  Hand h = make_map_c();
  State s0 = h.task->initial_state();
  DkgDistanceHeuristic d;
  // (has human gem1), C1: only the human can take gems. d = 5 moves, pickup
  // 5, n = 6 human actions, 5 robot turns in between at 0.6: 5 + 5 + 3 = 13.
  d.prepare(h.spec("(has human gem1)"), s0);
  EXPECT_NEAR(d.estimate(s0), 13.0, kEps);
  // (has human key2): the human (d 2): 2 + 5 + 2 x 0.6 = 8.2; the robot (d 2,
  // pickup 1, handover 1, 4 robot actions, 3 + 1 human turns (human active)
  // at 0.6): 2 + 1 + 1 + 2.4 = 6.4.
  d.prepare(h.spec("(has human key2)"), s0);
  EXPECT_NEAR(d.estimate(s0), 6.4, kEps);
  // Used keys are gone for good.
  State used = h.run({"(left human)", "(wait robot)", "(pickup human key1)", "(wait robot)", "(right human)",
                      "(wait robot)", "(unlock human key1 door1)"});
  d.prepare(h.spec("(has human key1)"), s0);
  EXPECT_EQ(d.estimate(used), model::kInf);
  // Goal reached: 0; atoms other than `has` count 0.
  State got = h.run({"(left human)", "(wait robot)", "(pickup human key1)"});
  EXPECT_EQ(d.estimate(got), 0.0);
  d.prepare(h.spec("(unlocked-by human door1)"), s0);
  EXPECT_EQ(d.estimate(s0), 0.0);

  // Map A: the robot fetches key1 for the human. While it holds the key, one
  // handover (1) remains, plus one human turn first when the human is active.
  Hand a = make_map_a();
  DkgDistanceHeuristic da;
  da.prepare(a.spec("(has human key1)"), a.task->initial_state());
  State held = a.run({"(wait human)", "(up robot)", "(wait human)", "(up robot)", "(wait human)",
                      "(pickup robot key1)"});
  EXPECT_NEAR(da.estimate(held), 1.6, kEps);
  held = a.task->apply(held, *a.task->find_action("(wait human)"));
  EXPECT_NEAR(da.estimate(held), 1.0, kEps);
}
