// `clips plan` time limits on a wide generated task (one 3-parameter action
// over 15 objects, written to a temp folder): both planners return soon after
// the limit, with a status and a message that say the limit was hit, never
// "no plan exists". Before the limits reached inside expansions and h_max,
// these runs went on for minutes.
#include <gtest/gtest.h>

#include <chrono>
#include <fstream>
#include <string>

#include "eval/support.hpp"
#include "search/wide_task.hpp"

namespace clips::eval {
namespace {

using testing::clips_binary;
using testing::contains;
using testing::run;

struct WideFiles {
  testing::TempDir dir{"wide"};
  std::string domain = (dir.path / "domain.pddl").string();
  std::string problem = (dir.path / "p.pddl").string();
  explicit WideFiles(int objects = 15, int links = 5) {
    std::ofstream(domain) << clips::testing::wide_domain_pddl();
    std::ofstream(problem) << clips::testing::wide_problem_pddl(objects, links);
  }
};

double timed_run(const std::string& args, testing::RunResult& r) {
  const auto t0 = std::chrono::steady_clock::now();
  r = run(clips_binary() + " plan " + args);
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

// Runs `clips plan` on the wide task with `flags` (a 2 s limit) and checks it
// stopped soon for that limit: exit 5, `status` in the output, `message`
// saying which limit, never "no plan exists".
void expect_stopped_by_limit(const std::string& flags, const std::string& status, const std::string& message) {
  WideFiles f;
  testing::RunResult r;
  const double secs = timed_run("--domain " + f.domain + " --problem " + f.problem + " --heuristic hmax " + flags, r);
  EXPECT_LT(secs, 30) << r.out;
  EXPECT_EQ(r.status, 5) << r.out;  // a limit stopped the search
  EXPECT_TRUE(contains(r.out, status)) << r.out;
  EXPECT_TRUE(contains(r.out, message)) << r.out;
  EXPECT_FALSE(contains(r.out, "no plan exists")) << r.out;
}

TEST(CliPlanLimits, AstarMaxSecondsHoldsOnAWideTask) {
  expect_stopped_by_limit("--max-seconds 2", "status max_time", "--max-seconds limit of 2 s reached");
}

TEST(CliPlanLimits, AstarTimeLimitHoldsOnAWideTask) {
  expect_stopped_by_limit("--time-limit 2 --json", "\"status\":\"time_limit\"", "time limit of 2 s reached");
}

TEST(CliPlanLimits, RtaaTimeLimitHoldsOnAWideTask) {
  expect_stopped_by_limit("--planner rtaa --time-limit 2", "status time_limit", "time limit of 2 s reached");
}

// The other side: a goal no action can reach (nothing adds `sealed`) is
// reported as "no plan exists", not as a limit.
TEST(CliPlanLimits, UnreachableGoalSaysNoPlanExists) {
  WideFiles f;
  testing::RunResult r;
  timed_run("--domain " + f.domain + " --problem " + f.problem + " --heuristic hmax --max-seconds 2" +
                " --goal '(sealed o1)'",
            r);
  EXPECT_EQ(r.status, 4) << r.out;  // no plan exists
  EXPECT_TRUE(contains(r.out, "status failure")) << r.out;
  EXPECT_TRUE(contains(r.out, "no plan exists")) << r.out;
  EXPECT_FALSE(contains(r.out, "limit")) << r.out;
}

// Grounding is part of the run: with 120 objects the wide action has 1.7
// million ground actions (about 15 s to ground here), and a raised
// --max-ground-actions lets it through; --max-seconds still holds.
TEST(CliPlanLimits, GroundingCountsInMaxSeconds) {
  WideFiles f(120, 1);
  testing::RunResult r;
  const double secs = timed_run("--domain " + f.domain + " --problem " + f.problem +
                                    " --max-ground-actions 100000000 --max-seconds 1",
                                r);
  EXPECT_LT(secs, 10) << r.out;
  EXPECT_EQ(r.status, 5) << r.out;
  EXPECT_TRUE(contains(r.out, "--max-seconds limit of 1 s reached while grounding")) << r.out;
  EXPECT_TRUE(contains(r.out, "ground actions reached so far")) << r.out;
}

// 8 million ground actions need about 8 GB: under a 1.5 GB address-space
// limit grounding stops early, saying why, instead of dying of bad_alloc
// (exit 7, memory) once the memory is gone.
TEST(CliPlanLimits, GroundingStopsBeforeMemoryRunsOut) {
#if defined(__SANITIZE_ADDRESS__) || defined(__SANITIZE_THREAD__)
  GTEST_SKIP() << "sanitizers reserve more address space than the limit";
#endif
  WideFiles f(200, 1);
  testing::RunResult r;
  const auto t0 = std::chrono::steady_clock::now();
  r = run("ulimit -v 1500000; " + clips_binary() + " plan --domain " + f.domain + " --problem " + f.problem +
          " --max-ground-actions 100000000");
  const double secs = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  EXPECT_LT(secs, 30) << r.out;
  EXPECT_EQ(r.status, 7) << r.out;
  EXPECT_TRUE(contains(r.out, "grounding is on course to need about")) << r.out;
  EXPECT_TRUE(contains(r.out, "action 'join'")) << r.out;
  EXPECT_TRUE(contains(r.out, "address-space limit")) << r.out;
  EXPECT_TRUE(contains(r.out, "stopped before memory ran out")) << r.out;
}

// A blind search on a 30-object wide task holds millions of states within
// seconds: --max-memory ends it with its own status, not "no plan exists".
TEST(CliPlanLimits, MaxMemoryStopsTheSearch) {
  WideFiles f(30, 6);
  testing::RunResult r;
  const double secs =
      timed_run("--domain " + f.domain + " --problem " + f.problem + " --heuristic blind --max-memory 200 --json", r);
  EXPECT_LT(secs, 60) << r.out;
  EXPECT_EQ(r.status, 5) << r.out;
  EXPECT_TRUE(contains(r.out, "\"status\":\"max_memory\"")) << r.out;
  EXPECT_TRUE(contains(r.out, "memory limit of 200 MiB reached")) << r.out;
  EXPECT_FALSE(contains(r.out, "no plan exists")) << r.out;
}

}  // namespace
}  // namespace clips::eval

// issue 44: `clips infer` and `clips assist` take a wall-clock limit on the
// whole call (the session engine's CallLimits). A limit far below what any
// inference takes stops every run: exit 5 and a message naming the limit.
namespace clips::eval {
namespace {

TEST(CliCallLimits, InferAndAssistStopAtTheirTimeLimit) {
  const std::string data = std::string(CLIPS_SOURCE_DIR) + "/data/examples/doors-keys-gems";
  const std::string adhoc = " --dataset " + data + " --problem e1 --actions '(left human) (wait robot) (left human)'";
  for (const std::string& cmd : {"infer --plan e1.1.keys --dataset " + data, "infer" + adhoc, "assist" + adhoc,
                                 "assist --plan e1.1.keys --dataset " + data}) {
    const testing::RunResult r = testing::run(testing::clips_binary() + " " + cmd + " --time-limit 0.000001");
    EXPECT_EQ(r.status, 5) << cmd << "\n" << r.out;
    EXPECT_TRUE(testing::contains(r.out, "--time-limit of 1e-06 s reached")) << cmd << "\n" << r.out;
    // A generous limit lets the run finish.
    const testing::RunResult ok = testing::run(testing::clips_binary() + " " + cmd + " --time-limit 600 --json");
    EXPECT_EQ(ok.status, 0) << cmd << "\n" << ok.out;
  }
  EXPECT_EQ(testing::run(testing::clips_binary() + " infer" + adhoc + " --time-limit -1").status, 2);
}

}  // namespace
}  // namespace clips::eval
