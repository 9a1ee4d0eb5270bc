#include "app/cli_input_test.hpp"

namespace clips::eval {
namespace cli_input_test {
// The fuzzed case: an unreachable goal on a dataset problem ran RTAA* for minutes.
TEST(CliPlan, RunTimeLimitStopsRtaaAndAstar) {
  if (!clips::paths::have_shared_dataset()) GTEST_SKIP() << "shared dataset not found";
  for (const std::string planner : {"rtaa", "astar"}) {
    const auto t0 = std::chrono::steady_clock::now();
    auto r = run(clips_binary() + " plan --dataset " + clips::paths::dkg_dataset() + " --problem 2 --planner " +
                 planner + " --goal '(> (xloc human) 100)' --time-limit 1" +
                 (planner == "rtaa" ? " --max-seconds 0.2" : ""));  // 0.2 s would end A*'s single search
    const double secs = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    EXPECT_EQ(r.status, 5) << planner << "\n" << r.out;
    EXPECT_TRUE(contains(r.out, "stopped: time limit of 1 s reached after")) << planner << "\n" << r.out;
    EXPECT_TRUE(contains(r.out, "status time_limit")) << planner << "\n" << r.out;
    EXPECT_LT(secs, 15) << planner;
  }
}

// Every gem of problem 2 for the human: optimal A* stops at its node budget
// (16.7 million expansions) and says how to get a plan anyway; that advice
// works: weighted A* with h_FF finds one within a second.
TEST(CliPlan, WeightedSearchFindsAPlanForEveryGem) {
  if (!clips::paths::have_shared_dataset()) GTEST_SKIP() << "shared dataset not found";
  const std::string base = clips_binary() + " plan --dataset " + clips::paths::dkg_dataset() +
                           " --problem 2 --goal '(forall (?g - gem) (has human ?g))'";
  auto stopped = run(base + " --max-nodes 20000");
  EXPECT_EQ(stopped.status, 5) << stopped.out;
  EXPECT_TRUE(contains(stopped.out, "try --heuristic hff --weight 5")) << stopped.out;
  auto r = run(base + " --heuristic hff --weight 5 --json");
  EXPECT_EQ(r.status, 0) << r.out;
  EXPECT_TRUE(contains(r.out, "\"status\":\"success\"")) << r.out;
  EXPECT_TRUE(contains(r.out, "\"weight\":5")) << r.out;
  EXPECT_TRUE(contains(r.out, "(pickup human gem1)") && contains(r.out, "(pickup human gem4)")) << r.out;
}

TEST(CliPlan, JsonReportsTheTimeLimitStatus) {
  if (!clips::paths::have_shared_dataset()) GTEST_SKIP() << "shared dataset not found";
  auto r = run(clips_binary() + " plan --dataset " + clips::paths::dkg_dataset() +
               " --problem 2 --planner rtaa --goal '(> (xloc human) 100)' --time-limit 0.5 --json");
  EXPECT_EQ(r.status, 5) << r.out;
  EXPECT_TRUE(contains(r.out, "\"status\":\"time_limit\"")) << r.out;
}

}  // namespace cli_input_test

}  // namespace clips::eval
