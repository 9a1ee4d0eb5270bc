// `clips bench`: its selection is checked before any plan runs, and its
// writers stay well-formed for failed plans and method subsets.
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include "eval/bench.hpp"
#include "eval/support.hpp"

namespace clips::eval {
namespace {

using testing::clips_binary;
using testing::examples_dkg;
using testing::run;

using testing::contains;
using testing::parse_csv;

size_t column(const std::vector<std::string>& header, const std::string& name) {
  for (size_t i = 0; i < header.size(); ++i)
    if (header[i] == name) return i;
  ADD_FAILURE() << "no column " << name;
  return 0;
}

// A successful `clips bench` on the repo's examples with `selection` (plans and
// methods): its console output, the rows of results.csv and summary.json.
struct BenchRun {
  std::string console, summary;
  std::vector<std::vector<std::string>> rows;
};
BenchRun run_bench(const std::string& tag, const std::string& selection) {
  testing::TempDir out(tag);
  const auto r = run(clips_binary() + " bench --dataset " + examples_dkg() + " " + selection +
                     " --no-progress --out " + out.str());
  EXPECT_EQ(r.status, 0) << r.out;
  BenchRun b{r.out, "", {}};
  if (r.status == 0) {
    b.rows = parse_csv(testing::read_text(out.path / "results.csv"));
    b.summary = testing::read_text(out.path / "summary.json");
  }
  return b;
}

BenchReport report_with_failures() {
  BenchReport r;
  r.domain = "doors-keys-gems";
  PlanOutcome ok;
  ok.plan_id = "1.1.keys";
  ok.goals = {"gem1", "gem2"};
  MethodResult clips;
  clips.method = "clips";
  clips.p_true_goal = 0.9;
  clips.goal_posterior = {0.9, 0.1};
  clips.options = {{"key1", 1.0}};
  clips.plan_length = 10;
  clips.rel_plan_length = 1;
  clips.rel_human_cost = 1;
  clips.has_relative = true;
  MethodResult mm;
  mm.method = "multimodal";
  mm.error = "reply from the chat endpoint: \"bad\", no JSON\nsecond line";
  ok.methods = {clips, mm};
  PlanOutcome failed;
  failed.plan_id = "2.1.keys";
  failed.seconds = 0.077;
  failed.error = "reply from the language model: \"oops\", status 500";
  r.plans = {ok, failed};
  r.failed_plans = 1;
  return r;
}

// Item 2: the failure row had 16 fields against the header's 15.
TEST(BenchCsv, EveryRowHasTheHeadersFieldCount) {
  const auto rows = parse_csv(results_csv(report_with_failures()));
  ASSERT_EQ(rows.size(), 4u);
  const auto& header = rows[0];
  EXPECT_EQ(header.size(), 18u);
  EXPECT_EQ(header[15], "domain");
  EXPECT_EQ(header[16], "requested");
  EXPECT_EQ(header.back(), "request_done");
  for (const auto& row : rows) EXPECT_EQ(row.size(), header.size()) << row[0];
  const auto& fail = rows[3];
  EXPECT_EQ(fail[0], "2.1.keys");
  EXPECT_EQ(fail[column(header, "seconds")], "0.077");
  EXPECT_EQ(fail[column(header, "options")], "");
  EXPECT_EQ(fail[column(header, "error")], "reply from the language model: \"oops\", status 500");
  EXPECT_TRUE(contains(rows[2][column(header, "error")], "second line"));
}

TEST(BenchTable, FailedPlansDoNotPointToAMissingCsv) {
  const std::string table = results_table(report_with_failures(), "/nonexistent.json");
  EXPECT_TRUE(contains(table, "1 plan(s) failed")) << table;
  EXPECT_TRUE(contains(table, "2.1.keys")) << table;
  EXPECT_FALSE(contains(table, "results.csv")) << table;
}

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
  std::ifstream in(out.path / "results.csv");
  std::stringstream text;
  text << in.rdbuf();
  const auto rows = parse_csv(text.str());
  ASSERT_EQ(rows.size(), 2u) << text.str();
  const auto& header = rows[0];
  const auto col = std::find(header.begin(), header.end(), "goal_success") - header.begin();
  ASSERT_LT(static_cast<size_t>(col), header.size());
  EXPECT_EQ(rows[1][static_cast<size_t>(col)], "1") << text.str();
}

}  // namespace
}  // namespace clips::eval
