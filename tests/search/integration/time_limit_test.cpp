// Time limits hold inside long expansions and long heuristic estimates: on a
// task with thousands of ground actions per state, A* and RTAA* with a short
// limit end soon after it with MaxTime. The bounds are generous (a correctness
// test of the limit, not a benchmark): without the checks these runs take
// minutes.
#include <gtest/gtest.h>

#include <chrono>
#include <memory>

#include "heuristics/basic.hpp"
#include "pddl/parser.hpp"
#include "search/rtaa.hpp"
#include "search/wide_task.hpp"

using namespace clips;
using clock_type = std::chrono::steady_clock;

namespace {

std::shared_ptr<model::Specification> wide_spec(int objects, int links) {
  auto d = std::make_shared<pddl::Domain>(pddl::parse_domain(clips::testing::wide_domain_pddl(), "wide-domain.pddl"));
  auto p = std::make_shared<pddl::Problem>(
      pddl::parse_problem(*d, clips::testing::wide_problem_pddl(objects, links), "wide-problem.pddl"));
  auto task = std::make_shared<pddl::Task>(d, p);
  return std::make_shared<model::Specification>(task, p->goal_sexpr->str(), model::unit_profile());
}

double seconds_since(clock_type::time_point t0) {
  return std::chrono::duration<double>(clock_type::now() - t0).count();
}

}  // namespace

TEST(TimeLimit, WideTaskHasThousandsOfGroundActions) {
  auto spec = wide_spec(15, 5);
  EXPECT_EQ(spec->task().num_actions(), 15 * 15 * 15);
  EXPECT_EQ(spec->task().applicable_actions(spec->task().initial_state()).size(), 15u * 15 * 15);
}

TEST(TimeLimit, AStarMaxSecondsHoldsInsideExpansions) {
  auto spec = wide_spec(15, 5);
  heuristics::HMaxHeuristic h;
  search::SearchOptions o;
  o.max_seconds = 1;
  const auto t0 = clock_type::now();
  auto r = search::plan(*spec, h, spec->task().initial_state(), o);
  const double secs = seconds_since(t0);
  EXPECT_EQ(r.status, search::SearchStatus::MaxTime);
  EXPECT_LT(secs, 10);
  EXPECT_GE(r.seconds, 1.0);
  EXPECT_GT(r.generated, 1u);
  // The search's deadline does not stay behind in the heuristic.
  EXPECT_EQ(h.deadline(), clock_type::time_point::max());
  EXPECT_FALSE(h.timed_out());
  EXPECT_EQ(h.estimate(spec->task().initial_state().data()), 1);
}

TEST(TimeLimit, AStarRunDeadlineHolds) {
  auto spec = wide_spec(15, 5);
  heuristics::HMaxHeuristic h;
  search::SearchOptions o;
  const auto t0 = clock_type::now();
  o.deadline = t0 + std::chrono::seconds(1);
  auto r = search::plan(*spec, h, spec->task().initial_state(), o);
  EXPECT_EQ(r.status, search::SearchStatus::MaxTime);
  EXPECT_LT(seconds_since(t0), 10);
}

TEST(TimeLimit, RtaaRefineHoldsTheRunDeadline) {
  auto spec = wide_spec(15, 5);
  auto h = std::make_shared<heuristics::HMaxHeuristic>();
  search::Policy pol(spec, h);
  search::SearchOptions o;
  const auto t0 = clock_type::now();
  o.deadline = t0 + std::chrono::seconds(1);
  auto st = pol.refine(spec->task().initial_state(), o);
  EXPECT_LT(seconds_since(t0), 10);
  EXPECT_GE(st.stopped_by_budget, 1u);
  // Estimates cut short were not cached: a fresh estimate is the real one.
  EXPECT_EQ(pol.value(spec->task().initial_state()), -1);
}

// One h_max estimate on a large grounding stops at a deadline already passed
// (and returns 0, which is admissible); without one it computes the value.
TEST(TimeLimit, HMaxEstimateStopsAtItsDeadline) {
  auto spec = wide_spec(25, 3);
  heuristics::HMaxHeuristic h;
  const pddl::State s0 = spec->task().initial_state();
  h.prepare(*spec, s0);
  EXPECT_EQ(h.estimate(s0.data()), 1);
  EXPECT_FALSE(h.timed_out());
  h.set_deadline(clock_type::now() - std::chrono::seconds(1));
  EXPECT_EQ(h.estimate(s0.data()), 0);
  EXPECT_TRUE(h.timed_out());
  h.set_deadline(clock_type::time_point::max());
  EXPECT_FALSE(h.timed_out());
  EXPECT_EQ(h.estimate(s0.data()), 1);
}
