#include "app/cli_input_test.hpp"

namespace clips::eval {
namespace cli_input_test {
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

TEST(CliPlan, HelpSaysBudgetsArePerSearchAndOffersARunLimit) {
  auto r = run(clips_binary() + " plan --help");
  ASSERT_EQ(r.status, 0) << r.out;
  EXPECT_TRUE(contains(r.out, "--time-limit")) << r.out;
  EXPECT_TRUE(contains(r.out, "each A* search")) << r.out;
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

}  // namespace cli_input_test

}  // namespace clips::eval
