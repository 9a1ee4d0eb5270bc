#pragma once
// The includes, helpers and fixtures of the search tests in dkg_heuristic_test.cpp, shared by
// the files of that name in tests/search/ and its label folders
// (docs/testing.md, "Labels").
// The Doors-Keys-Gems heuristics: the reference MST heuristic on hand-built
// maps whose room labels, room graph, key/door sets and values are worked out
// by hand below; its pruning; and the admissible distance heuristic checked
// against exact cost-to-go (a uniform-cost search written here) and for
// consistency on random walks over dataset problems.
#include <gtest/gtest.h>

#include <chrono>
#include <cmath>
#include <filesystem>
#include <iostream>
#include <limits>
#include <optional>
#include <queue>
#include <random>
#include <sstream>
#include <unordered_map>

#include "data/dataset.hpp"
#include "domains/dkg/dkg_heuristic.hpp"
#include "domains/dkg/dkg_map.hpp"
#include "pddl/parser.hpp"
#include "search/rtaa.hpp"
#include "test_paths.hpp"
#include "dkg_profiles.hpp"

using namespace clips;
using namespace clips::domains;
using namespace clips::domains::dkg;
using pddl::State;

namespace dkg_heuristic_test {

constexpr double kEps = 1e-9;

// ---------------------------------------------------------------- map builder

struct Obj {
  std::string name, type, color;
  int x = 0, y = 0;
  bool locked = false;
};

// rows: 'W' wall, anything else floor; objects placed by coordinates.
std::string problem_text(const std::vector<std::string>& rows, const std::vector<Obj>& objs, const std::string& goal) {
  const int H = static_cast<int>(rows.size()), W = static_cast<int>(rows[0].size());
  std::ostringstream o;
  o << "(define (problem hand) (:domain doors-keys-gems)\n (:objects red yellow blue green - color";
  for (auto& ob : objs) o << " " << ob.name << " - " << ob.type;
  o << ")\n (:init (= (walls) (new-bit-matrix false " << H << " " << W << "))\n";
  for (int y = 1; y <= H; ++y)
    for (int x = 1; x <= W; ++x)
      if (rows[y - 1][x - 1] == 'W') o << "  (= (walls) (set-index walls true " << y << " " << x << "))\n";
  for (auto& ob : objs) {
    o << "  (= (xloc " << ob.name << ") " << ob.x << ") (= (yloc " << ob.name << ") " << ob.y << ")\n";
    if (!ob.color.empty()) o << "  (iscolor " << ob.name << " " << ob.color << ")\n";
    if (ob.locked) o << "  (locked " << ob.name << ")\n";
    if (ob.type == "gem") o << "  (forbidden robot " << ob.name << ")\n";
  }
  o << "  (active human) (next-turn human robot) (next-turn robot human))\n (:goal " << goal << "))\n";
  return o.str();
}

struct Hand {
  std::shared_ptr<pddl::Domain> d;
  std::shared_ptr<const pddl::Task> task;

  Hand(const std::vector<std::string>& rows, const std::vector<Obj>& objs) {
    d = std::make_shared<pddl::Domain>(pddl::load_domain(paths::examples_dir() + "/doors-keys-gems/domain.pddl"));
    auto p = std::make_shared<pddl::Problem>(
        pddl::parse_problem(*d, problem_text(rows, objs, "(has human gem1)"), "hand.pddl"));
    task = std::make_shared<pddl::Task>(d, p, pddl::GroundingOptions{{"frozen"}, {}, false, false});
  }
  model::Specification spec(const std::string& goal, int profile = 1) const {
    return model::Specification(task, goal, fixtures::dkg_profile(profile));
  }
  State run(const std::vector<std::string>& steps) const {
    State s = task->initial_state();
    for (auto& step : steps) {
      auto a = task->find_action(step);
      EXPECT_TRUE(a) << step;
      if (!a) return s;
      EXPECT_TRUE(task->applicable(*a, s.data())) << step;
      s = task->apply(s, *a);
    }
    return s;
  }
  int idx(const DkgMapAnalysis& m, const std::string& name) const { return m.index_of(*task->find_object(name)); }
};

// Map A: 5 x 3, a locked red door between two rooms.
//   y=1:  k1 .  W  .  .
//   y=2:  h  .  D1 .  g1
//   y=3:  m  .  W  .  .
Hand make_map_a() {
  return Hand({"..W..", ".....", "..W.."},
              {{"human", "human", "", 1, 2}, {"robot", "robot", "", 1, 3}, {"key1", "key", "red", 1, 1},
               {"door1", "door", "red", 3, 2, true}, {"gem1", "gem", "red", 5, 2}});
}

// Map B: 7 x 3, two red doors in a row.
//   y=1:  k1 .  W  .  W  .  .
//   y=2:  h  .  D1 .  D2 .  g1
//   y=3:  k2 .  W  .  W  .  m
Hand make_map_b(bool two_keys) {
  std::vector<Obj> objs = {{"human", "human", "", 1, 2},         {"robot", "robot", "", 7, 3},
                           {"key1", "key", "red", 1, 1},         {"door1", "door", "red", 3, 2, true},
                           {"door2", "door", "red", 5, 2, true}, {"gem1", "gem", "red", 7, 2}};
  if (two_keys) objs.push_back({"key2", "key", "red", 1, 3});
  return Hand({"..W.W..", ".......", "..W.W.."}, objs);
}

// Map C: a 9 x 1 corridor.
//   x:  1  2  3  4  5  6  7  8  9
//       k1 h  D1 k2 D2 m  g1 D3 k3      (D1 red, D2 blue, D3 yellow; k1 red, k2 blue, k3 yellow)
Hand make_map_c() {
  return Hand({"........."},
              {{"human", "human", "", 2, 1}, {"robot", "robot", "", 6, 1}, {"key1", "key", "red", 1, 1},
               {"door1", "door", "red", 3, 1, true}, {"key2", "key", "blue", 4, 1},
               {"door2", "door", "blue", 5, 1, true}, {"gem1", "gem", "red", 7, 1},
               {"door3", "door", "yellow", 8, 1, true}, {"key3", "key", "yellow", 9, 1}});
}

// Map D: two routes to the gem room; the short one through a locked blue
// door whose key lies behind a locked green door, the long one through two
// unlocked doors (red door1, yellow door4).
//   x:    1  2  3  4  5
//   y=1:  k3 h  D2 .  g1
//   y=2:  D1 W  W  W  D4
//   y=3:  .  k1 m  k4 .
//   y=4:  W  W  D3 W  W
//   y=5:  W  W  k2 W  W
Hand make_map_d() {
  return Hand({".....", ".WWW.", ".....", "WW.WW", "WW.WW"},
              {{"human", "human", "", 2, 1}, {"robot", "robot", "", 3, 3}, {"key1", "key", "red", 2, 3},
               {"key2", "key", "blue", 3, 5}, {"key3", "key", "green", 1, 1}, {"key4", "key", "yellow", 4, 3},
               {"door1", "door", "red", 1, 2, false}, {"door2", "door", "blue", 3, 1, true},
               {"door3", "door", "green", 3, 4, true}, {"door4", "door", "yellow", 5, 2, false},
               {"gem1", "gem", "red", 5, 1}});
}

double mst(const Hand& h, const std::string& goal, const State& s, int profile = 1) {
  auto spec = h.spec(goal, profile);
  DkgMstHeuristic heur;
  heur.prepare(spec, h.task->initial_state());
  return heur.estimate(s);
}

// ------------------------------------------------------- exact cost-to-go

struct Exact {
  double cost = model::kInf;
  bool complete = false;  // false: the budget ran out before an answer
};

// Uniform-cost search over the full joint state space.
Exact exact_cost(const pddl::Task& t, const model::Specification& spec, const State& start, size_t budget) {
  std::unordered_map<State, double, pddl::StateHash> best;
  using Item = std::pair<double, size_t>;
  std::vector<State> states;
  std::priority_queue<Item, std::vector<Item>, std::greater<>> open;
  states.push_back(start);
  best[start] = 0;
  open.push({0, 0});
  std::vector<pddl::ActionId> acts;
  while (!open.empty()) {
    auto [g, i] = open.top();
    open.pop();
    State s = states[i];
    if (g > best[s] + kEps) continue;
    if (spec.is_goal(s)) return {g, true};
    if (states.size() > budget) return {model::kInf, false};
    t.applicable_actions(s.data(), acts);
    for (auto a : acts) {
      State n = t.apply(s, a);
      double ng = g + spec.cost(a);
      auto it = best.find(n);
      if (it != best.end() && it->second <= ng + kEps) continue;
      best[n] = ng;
      states.push_back(std::move(n));
      open.push({ng, states.size() - 1});
    }
  }
  return {model::kInf, true};
}

State random_walk(const pddl::Task& t, State s, int steps, std::mt19937& rng) {
  std::vector<pddl::ActionId> acts;
  for (int i = 0; i < steps; ++i) {
    t.applicable_actions(s.data(), acts);
    if (acts.empty()) break;
    s = t.apply(s, acts[std::uniform_int_distribution<size_t>(0, acts.size() - 1)(rng)]);
  }
  return s;
}

std::string dataset_dir() { return paths::dkg_dataset(); }

}  // namespace dkg_heuristic_test
using namespace dkg_heuristic_test;

// ======================================================= map analysis by hand

// ============================================================ MST values by hand

// =========================================================== distance heuristic

namespace dkg_heuristic_test {

// Problems of the dataset that are cheap enough for exact search.
const std::vector<std::string> kDatasetProblems = {"demo0", "demo1", "demo2", "1", "12", "15", "17", "18"};

}  // namespace dkg_heuristic_test
using namespace dkg_heuristic_test;

// ============================================ MST over-estimation
