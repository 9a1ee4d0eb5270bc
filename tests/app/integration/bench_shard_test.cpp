#include "app/bench_shard_test.hpp"

namespace clips::eval {
namespace bench_shard_test {
TEST_F(BenchShardTest, MergeOfThreeShardsEqualsTheUnshardedRun) {
  ASSERT_EQ(whole().status, 0) << whole().out;
  // Folders in another order than the shards': the merge puts the plans back in dataset order.
  const auto merged = run(merge_command(dir("merged").string(), {part(3), part(1), part(2)}));
  ASSERT_EQ(merged.status, 0) << merged.out;
  EXPECT_EQ(read_text(dir("merged") / "posteriors.csv"), read_text(dir("whole") / "posteriors.csv"));
  const auto rows = results_without_seconds(dir("merged"));
  EXPECT_EQ(rows.size(), 1u + 4 * 3);  // header, 4 plans x 3 methods
  EXPECT_EQ(rows, results_without_seconds(dir("whole")));
  EXPECT_EQ(summary_without_timing(dir("merged")), summary_without_timing(dir("whole")));
  EXPECT_EQ(plans_without_timing(dir("merged")), plans_without_timing(dir("whole")));
  // The table on stdout is the unsharded run's, but for its timing line.
  EXPECT_EQ(table_without_timing(merged.out), table_without_timing(whole().out));

  const json shards = json::parse(read_text(dir("merged") / "summary.json"))["shards"];
  EXPECT_EQ(shards["count"], 3);
  EXPECT_EQ(shards["present"], json({1, 2, 3}));
  EXPECT_EQ(shards["missing"], json::array());
  EXPECT_EQ(shards["partial"], false);
  EXPECT_FALSE(json::parse(read_text(dir("whole") / "summary.json")).contains("shards"));
}

// The examples' plans in dataset order: e1.1.keys, e1.2.keys, e2.1.doors, e2.2.keys.
TEST_F(BenchShardTest, PlansAreDealtRoundRobinInDatasetOrder) {
  EXPECT_EQ(plan_column(part(1)), (std::vector<std::string>{"e1.1.keys", "e2.2.keys"}));
  EXPECT_EQ(plan_column(part(2)), (std::vector<std::string>{"e1.2.keys"}));
  EXPECT_EQ(plan_column(part(3)), (std::vector<std::string>{"e2.1.doors"}));
  EXPECT_TRUE(contains(shard(1).out, "shard 1/3: 2 of the sweep's 4 plans")) << shard(1).out;
  const json s2 = json::parse(read_text(part(2) / "summary.json"));
  EXPECT_EQ(s2["plans"], 1);
  EXPECT_EQ(s2["shards"]["present"], json({2}));
  EXPECT_EQ(s2["shards"]["missing"], json({1, 3}));
  EXPECT_EQ(s2["shards"]["partial"], true);
  EXPECT_EQ(s2["shards"]["selection_plans"], 4);
}

TEST_F(BenchShardTest, MissingShardIsRefusedUnlessAllowPartial) {
  const auto refused = run(merge_command(dir("no-2").string(), {part(1), part(3)}));
  EXPECT_EQ(refused.status, 3) << refused.out;
  EXPECT_TRUE(contains(refused.out, "shard 2 of 3 is missing (the parts hold 1, 3)")) << refused.out;
  EXPECT_TRUE(contains(refused.out, "--allow-partial")) << refused.out;
  EXPECT_FALSE(fs::exists(dir("no-2") / "summary.json"));

  const auto partial = run(merge_command(dir("partial").string(), {part(1), part(3)}, "--allow-partial"));
  ASSERT_EQ(partial.status, 0) << partial.out;
  EXPECT_TRUE(contains(partial.out, "partial: shards 1, 3 of 3 (3 of the sweep's 4 plans); missing: 2")) << partial.out;
  const json j = json::parse(read_text(dir("partial") / "summary.json"));
  EXPECT_EQ(j["plans"], 3);
  EXPECT_EQ(j["shards"]["partial"], true);
  EXPECT_EQ(j["shards"]["missing"], json({2}));
  EXPECT_EQ(plan_column(dir("partial")), (std::vector<std::string>{"e1.1.keys", "e2.1.doors", "e2.2.keys"}));
}

// Merge checks, in this order: the parts' files, that they are of one run,
// shards and plans given twice, then missing shards; so each refusal below
// needs only the parts that provoke it.
TEST_F(BenchShardTest, DuplicateShardIsRefused) {
  const fs::path again = copy_of(1, "again");
  const auto r = run(merge_command(dir("dup").string(), {part(1), again}));
  EXPECT_EQ(r.status, 3) << r.out;
  EXPECT_TRUE(contains(r.out, "shard 1 of 3 is in both " + part(1).string() + " and " + again.string())) << r.out;
}

TEST_F(BenchShardTest, SamePlanInTwoPartsIsRefused) {
  // Shard 3's folder, edited to hold shard 2's plan as well.
  const fs::path edited = copy_of(3, "edited");
  json outcomes = json::parse(read_text(edited / "outcomes.json"));
  outcomes["plans"].push_back(json::parse(read_text(part(2) / "outcomes.json"))["plans"][0]);
  std::ofstream(edited / "outcomes.json") << outcomes.dump();
  const auto r = run(merge_command(dir("overlap").string(), {part(2), edited}));
  EXPECT_EQ(r.status, 3) << r.out;
  EXPECT_TRUE(contains(r.out, "plan e1.2.keys is in both " + part(2).string() + " and " + edited.string())) << r.out;
}

TEST_F(BenchShardTest, MismatchedSeedIsRefused) {
  const fs::path other = dir("seed-8");
  const auto shard = run(clips_binary() + kBench + " --seed 8 --shard 2/3 --out " + other.string());
  ASSERT_EQ(shard.status, 0) << shard.out;
  const auto r = run(merge_command(dir("mixed").string(), {part(1), other}));
  EXPECT_EQ(r.status, 3) << r.out;
  EXPECT_TRUE(contains(r.out, other.string() + "/outcomes.json: seed is 8, but " + part(1).string() +
                                  "/outcomes.json has 7"))
      << r.out;
}

TEST_F(BenchShardTest, MissingFileIsRefused) {
  const fs::path broken = copy_of(1, "no-posteriors");
  fs::remove(broken / "posteriors.csv");
  const auto r = run(merge_command(dir("missing-file").string(), {broken}));
  EXPECT_EQ(r.status, 3) << r.out;
  EXPECT_TRUE(contains(r.out, broken.string() + ": posteriors.csv is missing")) << r.out;
}

// issue 46: a damaged outcomes.json (goals empty or too few for the
// posteriors, the true goal out of range, ragged posteriors, a probability
// of 1e308) is refused naming the field, never a crash or a silent merge.
TEST_F(BenchShardTest, MalformedOutcomesAreRefusedNamingTheField) {
  struct Case {
    std::string name;
    std::function<void(json&)> edit;
    std::string message;
  };
  const std::vector<Case> cases = {
      {"goals-empty", [](json& p) { p["goals"] = json::array(); }, "plans[0].goals: is empty"},
      {"one-goal", [](json& p) { p["goals"] = json::array({"gem1"}); }, "plans[0].true_goal:"},
      {"one-goal-true-0",
       [](json& p) {
         p["goals"] = json::array({"gem1"});
         p["true_goal"] = 0;
       },
       "plans[0].goal_posterior_steps[0]: has"},
      {"true-goal-99", [](json& p) { p["true_goal"] = 99; }, "plans[0].true_goal: 99 is not the index"},
      {"true-goal-minus-1", [](json& p) { p["true_goal"] = -1; }, "plans[0].true_goal: -1 is not the index"},
      {"ragged", [](json& p) { p["methods"][0]["posterior_steps"][1].erase(0); },
       "plans[0].methods[0].posterior_steps[1]: has"},
      {"ragged-plan", [](json& p) { p["goal_posterior_steps"][0].push_back(0.5); },
       "plans[0].goal_posterior_steps[0]: has"},
      {"p-1e308", [](json& p) { p["methods"][0]["p_true_goal"] = 1e308; },
       "plans[0].methods[0].p_true_goal: 1e+308 is not a probability"},
      {"duplicate-goal", [](json& p) { p["goals"][1] = p["goals"][0]; }, "plans[0].goals: lists goal"},
      // issue 61: values no run writes, which the report would draw as they are.
      {"success-minus-1", [](json& p) { p["methods"][0]["goal_success"] = -1; },
       "plans[0].methods[0].goal_success: -1 is not a probability"},
      {"unknown-method", [](json& p) { p["methods"][0]["method"] = "telepathy"; },
       "plans[0].methods[0].method: 'telepathy' is not a method clips bench runs"},
      {"cost-1e308", [](json& p) { p["methods"][0]["rel_human_cost"] = 1e308; },
       "plans[0].methods[0].rel_human_cost: 1e+308 is not a length, cost or time"},
      {"length-minus-1", [](json& p) { p["methods"][0]["plan_length"] = -1; },
       "plans[0].methods[0].plan_length: -1 is not a length, cost or time"},
  };
  for (const auto& c : cases) {
    const fs::path edited = copy_of(1, "bad-" + c.name);
    json outcomes = json::parse(read_text(edited / "outcomes.json"));
    ASSERT_GE(outcomes["plans"][0]["goals"].size(), 2u);
    c.edit(outcomes["plans"][0]);
    std::ofstream(edited / "outcomes.json") << outcomes.dump();
    const auto r = run(merge_command(dir("merged-" + c.name).string(), {edited}, "--allow-partial"));
    EXPECT_EQ(r.status, 3) << c.name << ": " << r.out;
    EXPECT_TRUE(contains(r.out, edited.string() + "/outcomes.json: " + c.message)) << c.name << ": " << r.out;
  }
}

// issue 61: a shard with rel_human_cost 1e308 made `--report` draw an axis
// of 1e308 ticks (a 2 GB report); the merge now refuses it before any report.
TEST_F(BenchShardTest, AbsurdValuesAreRefusedBeforeTheReport) {
  const fs::path edited = copy_of(1, "absurd-report");
  json outcomes = json::parse(read_text(edited / "outcomes.json"));
  outcomes["plans"][0]["methods"][0]["rel_human_cost"] = 1e308;
  std::ofstream(edited / "outcomes.json") << outcomes.dump();
  const fs::path report = dir("absurd-report-html");
  const auto r = run("timeout 60 " +
                     merge_command(dir("absurd-merged").string(), {edited},
                                   "--allow-partial --dataset " + testing::examples_dkg() + " --report " +
                                       report.string()));
  EXPECT_EQ(r.status, 3) << r.out;
  EXPECT_TRUE(contains(r.out, "rel_human_cost: 1e+308")) << r.out;
  EXPECT_FALSE(fs::exists(report / "index.html"));
}

TEST(BenchShardCli, BadShardValuesAreUsageErrors) {
  testing::TempDir tmp("bench-bad-shard");
  for (const std::string bad : {"0/3", "4/3", "x", "3", "1/0", "1/", "/3", "-1/3", "1/3/3", "99999999999/3"}) {
    const auto r = run(clips_binary() + kBench + " --shard " + bad + " --out " + tmp.str());
    EXPECT_EQ(r.status, 2) << bad << ": " << r.out;
    EXPECT_TRUE(contains(r.out, "--shard")) << bad << ": " << r.out;
    EXPECT_FALSE(fs::exists(tmp.path / "results.csv")) << bad;
  }
  EXPECT_TRUE(contains(run(clips_binary() + kBench + " --shard 4/3").out, "K must be from 1 to N (3)"));
  EXPECT_TRUE(contains(run(clips_binary() + kBench + " --shard 1/0").out, "N must be at least 1"));
}

// More shards than plans: the empty shard writes files with no rows, says so,
// and merges like any other.
TEST(BenchShardCli, EmptyShardWritesValidFilesAndMerges) {
  testing::TempDir tmp("bench-empty-shard");
  const std::string one_plan = clips_binary() + kBench + " --plans e1.1.keys";
  const auto first = run(one_plan + " --shard 1/2 --out " + tmp.str() + "/1");
  ASSERT_EQ(first.status, 0) << first.out;
  const auto empty = run(one_plan + " --shard 2/2 --out " + tmp.str() + "/2");
  ASSERT_EQ(empty.status, 0) << empty.out;
  EXPECT_TRUE(contains(empty.out, "shard 2/2 has no plans")) << empty.out;
  EXPECT_EQ(parse_csv(read_text(tmp.path / "2" / "results.csv")).size(), 1u);  // the header
  EXPECT_EQ(read_text(tmp.path / "2" / "posteriors.csv"), "domain,plan,method,t,goal,probability\n");
  const json summary = json::parse(read_text(tmp.path / "2" / "summary.json"));
  EXPECT_EQ(summary["plans"], 0);
  EXPECT_EQ(summary["methods"], json::object());
  EXPECT_EQ(json::parse(read_text(tmp.path / "2" / "outcomes.json"))["plans"], json::array());

  const auto merged = run(merge_command(tmp.str() + "/merged", {tmp.path / "2", tmp.path / "1"}));
  ASSERT_EQ(merged.status, 0) << merged.out;
  EXPECT_EQ(results_without_seconds(tmp.path / "merged"), results_without_seconds(tmp.path / "1"));
  EXPECT_EQ(read_text(tmp.path / "merged" / "posteriors.csv"), read_text(tmp.path / "1" / "posteriors.csv"));
  EXPECT_EQ(json::parse(read_text(tmp.path / "merged" / "summary.json"))["shards"]["partial"], false);
}

// A plan that does not load is one of the sweep's plans, placed after the
// others: its shard reports it as failed, and the merge puts it last again.
TEST(BenchShardCli, UnloadablePlanIsShardedAndMergedLikeTheOthers) {
  testing::TempDir tmp("bench-shard-broken");
  const fs::path ds = tmp.path / "dkg";
  fs::copy(examples_dkg(), ds, fs::copy_options::recursive);
  std::ofstream(ds / "plans/observed/e1.2.keys.pddl") << "(up human)\n; Can you help\n(wait robot)\n; me?\n";
  const std::string bench = clips_binary() + " bench --dataset " + ds.string() + " --methods clips --no-progress";
  EXPECT_EQ(run(bench + " --out " + tmp.str() + "/whole").status, 1);  // 1: some plans failed
  EXPECT_EQ(run(bench + " --shard 1/2 --out " + tmp.str() + "/1").status, 0);
  EXPECT_EQ(run(bench + " --shard 2/2 --out " + tmp.str() + "/2").status, 1);  // positions 1 and 3 (the broken one)
  const auto merged = run(merge_command(tmp.str() + "/merged", {tmp.path / "1", tmp.path / "2"}));
  EXPECT_EQ(merged.status, 1) << merged.out;
  EXPECT_EQ(plan_column(tmp.path / "merged"),
            (std::vector<std::string>{"e1.1.keys", "e2.1.doors", "e2.2.keys", "e1.2.keys"}));
  EXPECT_EQ(results_without_seconds(tmp.path / "merged"), results_without_seconds(tmp.path / "whole"));
  EXPECT_EQ(summary_without_timing(tmp.path / "merged"), summary_without_timing(tmp.path / "whole"));
}

}  // namespace bench_shard_test

}  // namespace clips::eval
