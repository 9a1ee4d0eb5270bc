#pragma once
// The includes, helpers and fixtures of the app tests in bench_cli_test.cpp, shared by
// the files of that name in tests/app/ and its label folders
// (docs/testing.md, "Labels").
// `clips bench`: its selection is checked before any plan runs, and its
// writers stay well-formed for failed plans and method subsets.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <set>
#include <string>
#include <vector>

#include "eval/bench.hpp"
#include "eval/support.hpp"

namespace clips::eval {
namespace bench_cli_test {

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

}  // namespace bench_cli_test
using namespace bench_cli_test;
}  // namespace clips::eval
