#pragma once
// The includes, helpers and fixtures of the search tests in strips_export_test.cpp, shared by
// the files of that name in tests/search/ and its label folders
// (docs/testing.md, "Labels").
// Plain-STRIPS export of mDKG problems: the exported task, parsed and grounded
// by our own PDDL stack and solved by our A*, has the same optimal cost (after
// dividing by cost_scale) as the original task, and its plans map back to
// valid original plans of that cost.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <cstdio>
#include <filesystem>
#include <limits>
#include <set>

#include "data/dataset.hpp"
#include "domains/dkg/dkg_strips.hpp"
#include "heuristics/basic.hpp"
#include "pddl/parser.hpp"
#include "pddl/plan.hpp"
#include "search/astar.hpp"
#include "test_paths.hpp"
#include "dkg_profiles.hpp"

using namespace clips;

namespace strips_export_test {

struct Outcome {
  bool solved = false;
  double cost = 0;
};

// Optimal cost on the original task, and on the export (divided by the scale),
// plus a replay of the exported plan on the original task.
// Returns false (and checks nothing) when the original search exceeds
// `budget` expansions, so the dataset test can bound its running time.
bool check_equivalent(const std::shared_ptr<const pddl::Task>& task, const pddl::State& start, int gem, int profile,
                      const std::string& label, size_t budget = std::numeric_limits<size_t>::max()) {
  std::string goal = "(has human gem" + std::to_string(gem) + ")";
  SCOPED_TRACE(label + " " + goal + " C" + std::to_string(profile));
  model::Specification orig(task, goal, fixtures::dkg_profile(profile));
  heuristics::HMaxHeuristic h1;
  search::SearchOptions so;
  so.max_nodes = budget;
  auto r1 = search::plan(orig, h1, start, so);
  if (r1.status == search::SearchStatus::MaxNodes) return false;

  auto ex = domains::dkg::export_strips(*task, start, goal, fixtures::dkg_profile(profile));
  EXPECT_EQ(ex.cost_scale, 5);
  auto d = std::make_shared<pddl::Domain>(pddl::parse_domain(ex.domain, "<exported domain>"));
  auto p = std::make_shared<pddl::Problem>(pddl::parse_problem(*d, ex.problem, "<exported problem>"));
  auto etask = std::make_shared<pddl::Task>(d, p);  // default grounding options
  model::Specification espec(etask, goal, model::task_costs_profile());
  heuristics::HMaxHeuristic h2;
  auto r2 = search::plan(espec, h2, etask->initial_state());

  if (r1.status == search::SearchStatus::Failure) {
    EXPECT_EQ(r2.status, search::SearchStatus::Failure);
    return true;
  }
  EXPECT_EQ(r1.status, search::SearchStatus::Success);
  EXPECT_EQ(r2.status, search::SearchStatus::Success);
  if (r1.status != search::SearchStatus::Success || r2.status != search::SearchStatus::Success) return true;
  EXPECT_NEAR(r2.cost / ex.cost_scale, r1.cost, 1e-9);

  // Map the exported plan back and replay it on the original task.
  std::vector<pddl::ActionId> mapped;
  pddl::State s = start;
  double cost = 0;
  for (auto a : r2.plan) {
    std::string text = domains::dkg::to_original_action(etask->action_name(a));
    auto oa = task->find_action(text);
    EXPECT_TRUE(oa.has_value()) << text;
    if (!oa) return true;
    EXPECT_TRUE(task->applicable(*oa, s.data())) << text << "\n" << task->state_str(s);
    if (!task->applicable(*oa, s.data())) return true;
    s = task->apply(s, *oa);
    cost += orig.cost(*oa);
    mapped.push_back(*oa);
  }
  auto sim = pddl::simulate(*task, start, mapped);
  EXPECT_TRUE(orig.is_goal(sim.states.back()));
  EXPECT_NEAR(cost, r1.cost, 1e-9);
  return true;
}

data::Dataset examples() { return data::Dataset::load(paths::examples_dir() + "/doors-keys-gems"); }

}  // namespace strips_export_test
using namespace strips_export_test;
