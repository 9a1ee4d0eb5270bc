// The `clips` command line on bad input: options and values that are refused
// at parse time or before any work, with messages that name the problem.
#include <gtest/gtest.h>

#include <chrono>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "eval/support.hpp"
#include "test_paths.hpp"

namespace clips::eval {
namespace {

using testing::clips_binary;
using testing::examples_dkg;
using testing::run;

using testing::contains;

std::string quoted(const std::string& s) { return "'" + s + "'"; }

// --- numeric options (item 6) ---------------------------------------------

struct BadValue {
  std::string args;    // after `clips`
  std::string option;  // named in the message
};

TEST(CliNumbers, BadValuesAreRefusedAtParseTime) {
  const std::string ds = " --dataset " + examples_dkg();
  const std::string plan = "plan" + ds + " --problem e1";
  const std::vector<BadValue> cases = {
      {plan + " --max-nodes 0", "--max-nodes"},
      {plan + " --max-nodes -1", "--max-nodes"},
      {plan + " --max-seconds nan", "--max-seconds"},
      {plan + " --max-seconds inf", "--max-seconds"},
      {plan + " --max-seconds -1", "--max-seconds"},
      {plan + " --max-seconds 0", "--max-seconds"},
      {plan + " --planner rtaa --max-steps -5", "--max-steps"},
      {plan + " --planner rtaa --max-steps 0", "--max-steps"},
      {plan + " --time-limit nan", "--time-limit"},
      {plan + " --time-limit -3", "--time-limit"},
      {"bench" + ds + " --plans e1.1.keys -j 0", "--jobs"},
      {"bench" + ds + " --plans e1.1.keys -j -4", "--jobs"},
      {"listen" + ds + " --plan e1.1.keys --top 0", "--top"},
      {"listen" + ds + " --plan e1.1.keys --top -1", "--top"},
      {"infer" + ds + " --plan e1.1.keys --explain --top 0", "--top"},
      {"infer" + ds + " --plan e1.1.keys --max-nodes 0", "--max-nodes"},
      {"infer" + ds + " --plan e1.1.keys --max-nodes -1", "--max-nodes"},
      {"show" + ds + " --plan e1.1.keys --step -5", "--step"},
      {"render" + ds + " --plan e1.1.keys --out /dev/null --step -1", "--step"},
  };
  for (const auto& c : cases) {
    auto r = run(clips_binary() + " " + c.args);
    EXPECT_NE(r.status, 0) << c.args << "\n" << r.out;
    EXPECT_TRUE(contains(r.out, c.option)) << c.args << "\n" << r.out;
    EXPECT_FALSE(contains(r.out, "1.79769e+308")) << c.args << "\n" << r.out;
    EXPECT_FALSE(contains(r.out, "; status")) << c.args << " ran\n" << r.out;
  }
}

TEST(CliNumbers, GoodValuesStillParse) {
  auto r = run(clips_binary() + " show --dataset " + examples_dkg() + " --plan e1.1.keys --step 0");
  EXPECT_EQ(r.status, 0) << r.out;
  EXPECT_TRUE(contains(r.out, "step 0/")) << r.out;
  r = run(clips_binary() + " plan --dataset " + examples_dkg() +
          " --problem e1 --max-nodes 100000 --max-seconds 30 --time-limit 30");
  EXPECT_EQ(r.status, 0) << r.out;
  EXPECT_TRUE(contains(r.out, "status success")) << r.out;
}

// --- show --step (item 5) --------------------------------------------------

TEST(CliShow, NegativeStepIsRejectedNotTheLastStep) {
  auto r = run(clips_binary() + " show --dataset " + examples_dkg() + " --plan e1.1.keys --step -5");
  EXPECT_NE(r.status, 0) << r.out;
  EXPECT_FALSE(contains(r.out, "plan e1.1.keys (problem")) << r.out;
}

// --- plan (items 1 and 7) --------------------------------------------------

TEST(CliPlan, HelpSaysBudgetsArePerSearchAndOffersARunLimit) {
  auto r = run(clips_binary() + " plan --help");
  ASSERT_EQ(r.status, 0) << r.out;
  EXPECT_TRUE(contains(r.out, "--time-limit")) << r.out;
  EXPECT_TRUE(contains(r.out, "each A* search")) << r.out;
}

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

TEST(CliPlan, EmptyGoalsAreRejected) {
  for (const std::string goal : {"", " ", "()", "(and)"}) {
    auto r = run(clips_binary() + " plan --dataset " + examples_dkg() + " --problem e1 --goal " + quoted(goal));
    EXPECT_NE(r.status, 0) << quoted(goal) << "\n" << r.out;
    EXPECT_TRUE(contains(r.out, "empty")) << quoted(goal) << "\n" << r.out;
    EXPECT_FALSE(contains(r.out, "status success")) << quoted(goal) << "\n" << r.out;
  }
}

TEST(CliPlan, ProblemMustMatchFromPlan) {
  auto r = run(clips_binary() + " plan --dataset " + examples_dkg() + " --problem e2 --from-plan e1.1.keys");
  EXPECT_NE(r.status, 0) << r.out;
  EXPECT_TRUE(contains(r.out, "plan e1.1.keys is on problem e1, not e2")) << r.out;
  r = run(clips_binary() + " plan --dataset " + examples_dkg() + " --problem e1 --from-plan e1.1.keys");
  EXPECT_EQ(r.status, 0) << r.out;
}

// --- unknown subcommand (item 8) -------------------------------------------

TEST(CliMain, UnknownSubcommandIsNamedWithTheValidOnes) {
  auto r = run(clips_binary() + " foo");
  EXPECT_NE(r.status, 0) << r.out;
  EXPECT_TRUE(contains(r.out, "unknown subcommand 'foo'")) << r.out;
  for (const char* sub : {"validate", "plan", "bench", "render"}) EXPECT_TRUE(contains(r.out, sub)) << r.out;
  r = run(clips_binary());
  EXPECT_NE(r.status, 0) << r.out;
  EXPECT_TRUE(contains(r.out, "subcommand is required")) << r.out;
}

// --- listen (item 9) -------------------------------------------------------

TEST(CliListen, EmptyLiteralUtteranceFileIsNamed) {
  testing::TempDir tmp("listen-empty");
  const auto ds = tmp.path / "dkg";
  std::filesystem::copy(examples_dkg(), ds, std::filesystem::copy_options::recursive);
  const auto lit = ds / "utterances" / "literal" / "e1.1.keys.txt";
  std::ofstream(lit, std::ios::trunc).close();
  auto r = run(clips_binary() + " listen --dataset " + ds.string() + " --plan e1.1.keys");
  EXPECT_NE(r.status, 0) << r.out;
  EXPECT_TRUE(contains(r.out, "utterances/literal/e1.1.keys.txt is empty")) << r.out;
  EXPECT_FALSE(contains(r.out, "--utterance is empty")) << r.out;
}

}  // namespace
}  // namespace clips::eval
