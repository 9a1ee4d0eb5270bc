#include "app/bench_cli_test.hpp"

namespace clips::eval {
namespace bench_cli_test {
// Item 3: without clips there is no reference for the relative metrics.
TEST(BenchCli, RelativeMetricsAreNotApplicableWithoutClips) {
  const BenchRun b = run_bench("bench-naive", "--plans e1.1.keys --methods literal_naive");
  EXPECT_TRUE(contains(b.console, "n/a")) << b.console;
  const auto& rows = b.rows;
  ASSERT_EQ(rows.size(), 2u);
  for (const auto& row : rows) ASSERT_EQ(row.size(), rows[0].size());
  EXPECT_EQ(rows[1][column(rows[0], "method")], "literal_naive");
  EXPECT_EQ(rows[1][column(rows[0], "rel_plan_length")], "");
  EXPECT_EQ(rows[1][column(rows[0], "rel_human_cost")], "");
  EXPECT_NE(rows[1][column(rows[0], "plan_length")], "");
  EXPECT_FALSE(contains(b.summary, "rel_plan_length")) << b.summary;
}

TEST(BenchCli, RelativeMetricsAreKeptWithClips) {
  const auto rows = run_bench("bench-clips", "--plans e1.1.keys --methods clips literal_naive").rows;
  ASSERT_EQ(rows.size(), 3u);
  for (size_t i = 1; i < rows.size(); ++i) {
    EXPECT_NE(rows[i][column(rows[0], "rel_plan_length")], "") << rows[i][1];
    EXPECT_NE(rows[i][column(rows[0], "rel_human_cost")], "") << rows[i][1];
  }
  EXPECT_EQ(rows[1][column(rows[0], "rel_plan_length")], "1");
}

// Lists may also be written with commas, as in most tools.
TEST(BenchCli, MethodAndPlanListsAcceptCommas) {
  const auto rows = run_bench("bench-commas", "--plans e1.1.keys,e2.1.doors --methods clips,literal_naive").rows;
  ASSERT_EQ(rows.size(), 5u);  // header + 2 plans x 2 methods
  std::set<std::string> seen;
  for (size_t i = 1; i < rows.size(); ++i)
    seen.insert(rows[i][column(rows[0], "plan")] + "/" + rows[i][column(rows[0], "method")]);
  EXPECT_EQ(seen, (std::set<std::string>{"e1.1.keys/clips", "e1.1.keys/literal_naive", "e2.1.doors/clips",
                                         "e2.1.doors/literal_naive"}));
}

// Item 4: names and paths are checked before the run.
TEST(BenchCli, UnknownPlansAndMethodsAreErrors) {
  const std::string bench = clips_binary() + " bench --no-progress --dataset " + examples_dkg();
  auto r = run(bench + " --plans e1.1.keys nope");
  EXPECT_NE(r.status, 0) << r.out;
  EXPECT_TRUE(contains(r.out, "unknown plan id nope")) << r.out;
  EXPECT_TRUE(contains(r.out, "e2.1.doors")) << r.out;  // the valid ids are listed
  EXPECT_FALSE(contains(r.out, "P(g_true)")) << r.out;  // no table: nothing ran

  r = run(bench + " --plans e1.1.keys --methods foo");
  EXPECT_NE(r.status, 0) << r.out;
  EXPECT_TRUE(contains(r.out, "unknown method foo")) << r.out;
  EXPECT_TRUE(contains(r.out, "literal_naive")) << r.out;
  EXPECT_FALSE(contains(r.out, "results.csv")) << r.out;

  r = run(bench + " --plans e1.1.keys --methods literal");  // VirtualHome's literal listener
  EXPECT_NE(r.status, 0) << r.out;
  EXPECT_TRUE(contains(r.out, "unknown method literal for a doors-keys-gems dataset")) << r.out;
}

TEST(BenchCli, OutputAndDatasetMustBeDirectories) {
  testing::TempDir tmp("bench-paths");
  const auto file = tmp.path / "afile";
  std::ofstream(file) << "x\n";
  auto r = run(clips_binary() + " bench --no-progress --dataset " + examples_dkg() +
               " --plans e1.1.keys --methods literal_naive --out " + file.string());
  EXPECT_NE(r.status, 0) << r.out;
  EXPECT_TRUE(contains(r.out, "is not a directory")) << r.out;
  EXPECT_FALSE(contains(r.out, "P(g_true)")) << r.out;  // failed before the run

  r = run(clips_binary() + " bench --no-progress --dataset " + file.string());
  EXPECT_NE(r.status, 0) << r.out;
  EXPECT_TRUE(contains(r.out, "is not a directory")) << r.out;
  EXPECT_FALSE(contains(r.out, "does not exist")) << r.out;
}

// The garden's plan 7.6 asks the robot to get the fern out of the locked
// greenhouse. Having fetched the key and the fern, the robot hands the key
// over; what was asked then needs the key back from the human, and a plan
// that starts by waiting for that is no step towards it: the robot does not
// wait for it while both wait out the horizon, and the fern gets planted.
TEST(BenchCli, ARequestHandedBackIsNotWaitedForUntilTheHorizon) {
  testing::TempDir out("bench-handed-back");
  const auto r = run(clips_binary() + " bench --no-progress --methods clips --dataset " + std::string(CLIPS_SOURCE_DIR) +
                     "/data/datasets/garden --plans 7.6.repot-fern --out " + out.str());
  ASSERT_EQ(r.status, 0) << r.out;
  const auto rows = parse_csv(testing::read_text(out.path / "results.csv"));
  ASSERT_EQ(rows.size(), 2u);
  EXPECT_EQ(rows[1][column(rows[0], "goal_success")], "1");
}

}  // namespace bench_cli_test

}  // namespace clips::eval
