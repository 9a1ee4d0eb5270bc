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
#include "domains/dkg_strips.hpp"
#include "heuristics/basic.hpp"
#include "pddl/parser.hpp"
#include "pddl/plan.hpp"
#include "search/astar.hpp"
#include "test_paths.hpp"
#include "dkg_profiles.hpp"

using namespace clips;

namespace {

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

  auto ex = domains::export_strips(*task, start, goal, fixtures::dkg_profile(profile));
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
    std::string text = domains::to_original_action(etask->action_name(a));
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

}  // namespace

TEST(StripsExport, SameOptimalCostOnExampleProblems) {
  auto ds = examples();
  for (const char* p : {"e1", "e2"})
    for (int g = 1; g <= 4; ++g)
      for (int c = 1; c <= 4; ++c) {
        auto task = ds.task(p);
        check_equivalent(task, task->initial_state(), g, c, p);
      }
}

// Mid-plan start states: the robot may be active, items held or consumed and
// doors already open.
TEST(StripsExport, SameOptimalCostFromMidPlanStates) {
  auto ds = examples();
  for (const char* p : {"e1", "e2"})
    for (int g = 1; g <= 4; ++g) {
      auto task = ds.task(p);
      model::Specification spec(task, "(has human gem" + std::to_string(g) + ")", fixtures::dkg_profile(3));
      heuristics::HMaxHeuristic h;
      auto r = search::plan(spec, h, task->initial_state());
      // Every gem of the examples is reachable: a failed search is a bug, not a case to skip.
      ASSERT_EQ(r.status, search::SearchStatus::Success) << p << " gem" << g << ": " << search::to_string(r.status);
      ASSERT_GE(r.plan.size(), 2u) << p << " gem" << g;
      auto sim = pddl::simulate(*task, task->initial_state(), r.plan);
      for (size_t k = 1; k < sim.states.size(); k += 3)
        EXPECT_TRUE(check_equivalent(task, sim.states[k], g, 1 + static_cast<int>(k % 4),
                                     std::string(p) + " step " + std::to_string(k)));
    }
}

TEST(StripsExport, FrozenRobotMayOnlyWaitOrHandOver) {
  auto ds = examples();
  for (const char* p : {"e1", "e2"}) {
    auto task = ds.task(p);
    auto frozen = model::freeze(*task, task->initial_state(), "robot");
    auto ex = domains::export_strips(*task, frozen, "(has human gem1)", fixtures::dkg_profile(1));
    EXPECT_EQ(ex.problem.find("(unfrozen robot)"), std::string::npos);
    EXPECT_NE(ex.problem.find("(unfrozen human)"), std::string::npos);
    for (int g = 1; g <= 4; ++g)
      for (int c : {1, 4}) check_equivalent(task, frozen, g, c, std::string(p) + " frozen robot");
  }
}

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

TEST(StripsExport, CostScale) {
  for (int c = 1; c <= 4; ++c) {
    std::vector<double> costs;
    auto prof = fixtures::dkg_profile(c);
    for (auto& [k, v] : prof.costs) costs.push_back(v);
    EXPECT_EQ(domains::integer_cost_scale(costs), 5) << "C" << c;
  }
  EXPECT_EQ(domains::integer_cost_scale({1, 2, 5}), 1);
  EXPECT_EQ(domains::integer_cost_scale({0.25, 1}), 4);
  EXPECT_EQ(domains::integer_cost_scale({1.0 / 3, 0.5}), 6);
  EXPECT_THROW(domains::integer_cost_scale({std::sqrt(2.0)}), InputError);
  EXPECT_THROW(domains::integer_cost_scale({-1}), InputError);
  auto task = examples().task("e1");
  EXPECT_EQ(domains::export_strips(*task, task->initial_state(), "(has human gem2)", model::unit_profile()).cost_scale,
            1);
  // The scaled costs appear in the domain: human wait 0.6 -> 3, human pickup 5 -> 25.
  auto ex = domains::export_strips(*task, task->initial_state(), "(has human gem2)", fixtures::dkg_profile(1));
  EXPECT_NE(ex.domain.find("(:action wait-human"), std::string::npos);
  EXPECT_NE(ex.domain.find("(increase (total-cost) 3)"), std::string::npos);
  EXPECT_NE(ex.domain.find("(increase (total-cost) 25)"), std::string::npos);
  EXPECT_NE(ex.domain.find(":requirements :strips :typing :action-costs"), std::string::npos);
  EXPECT_NE(ex.problem.find("(:metric minimize (total-cost))"), std::string::npos);
}

TEST(StripsExport, ConjunctiveGoalsAndUnsupportedGoals) {
  auto ds = examples();
  auto task = ds.task("e1");
  auto s0 = task->initial_state();
  // A conjunction of has atoms is exported and stays equivalent.
  std::string goal = "(and (has human gem1) (has human gem2))";
  auto ex = domains::export_strips(*task, s0, goal, fixtures::dkg_profile(1));
  EXPECT_EQ(ex.goal, "(and (has human gem1) (has human gem2))");
  model::Specification orig(task, goal, fixtures::dkg_profile(1));
  heuristics::HMaxHeuristic h1, h2;
  auto r1 = search::plan(orig, h1, s0);
  auto d = std::make_shared<pddl::Domain>(pddl::parse_domain(ex.domain, "d"));
  auto p = std::make_shared<pddl::Problem>(pddl::parse_problem(*d, ex.problem, "p"));
  auto et = std::make_shared<pddl::Task>(d, p);
  model::Specification es(et, goal, model::task_costs_profile());
  auto r2 = search::plan(es, h2, et->initial_state());
  ASSERT_EQ(r1.status, search::SearchStatus::Success);
  ASSERT_EQ(r2.status, search::SearchStatus::Success);
  EXPECT_NEAR(r2.cost / ex.cost_scale, r1.cost, 1e-9);

  auto prof = fixtures::dkg_profile(1);
  for (const char* bad : {"(or (has human gem1) (has human gem2))", "(not (has human gem1))", "(locked door1)",
                          "(has human)", "(has human door1)", "(has nobody gem1)", "(and)"}) {
    try {
      domains::export_strips(*task, s0, bad, prof);
      ADD_FAILURE() << "accepted " << bad;
    } catch (const InputError& e) {
      EXPECT_NE(std::string(e.what()).find("has"), std::string::npos) << bad << ": " << e.what();
    }
  }
  EXPECT_THROW(domains::export_strips(*task, s0, "(has human gem1)", model::task_costs_profile()), InputError);
}

TEST(StripsExport, ActionMapping) {
  EXPECT_EQ(domains::to_original_action("(move-up-human c_5_3 c_5_2)"), "(up human)");
  EXPECT_EQ(domains::to_original_action("(move-right-robot c_5_3 c_6_3)"), "(right robot)");
  EXPECT_EQ(domains::to_original_action("(pickup-robot key1 c_1_3)"), "(pickup robot key1)");
  EXPECT_EQ(domains::to_original_action("(unlock-human key1 door1 c_3_2 c_3_1)"), "(unlock human key1 door1)");
  EXPECT_EQ(domains::to_original_action("(handover-robot-human key2 c_5_4 c_5_3)"), "(handover robot human key2)");
  EXPECT_EQ(domains::to_original_action("(wait-robot)"), "(wait robot)");
  EXPECT_EQ(domains::to_original_action("(WAIT-HUMAN)"), "(wait human)");
  for (const char* bad : {"(up human)", "(move-up-human c_1_1)", "(handover-human key1 c_1_1 c_1_2)", "wait-human",
                          "(pickup- key1 c_1_1)"})
    EXPECT_THROW(domains::to_original_action(bad), InputError) << bad;
}
