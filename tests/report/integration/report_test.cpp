#include "report/report_test.hpp"

namespace clips::report {
namespace report_test {
TEST_F(BenchReportTest, SummaryJson) {
  ASSERT_EQ(result_->status, 0) << result_->out;
  auto j = nlohmann::json::parse(testing::read_text(tmp_->path / "summary.json"));
  for (const char* k : {"domain", "dataset", "plans", "failed_plans", "lm", "wall_seconds", "max_rss_mb", "methods"})
    EXPECT_TRUE(j.contains(k)) << k;
  EXPECT_EQ(j["domain"], "doors-keys-gems");
  // The speaker-model choices that produced the numbers (defaults: the paper's).
  EXPECT_EQ(j.value("speaker_rule", ""), "paper");
  EXPECT_EQ(j.value("utterance_timing", ""), "after");
  EXPECT_EQ(j["plans"], kPlans.size());
  EXPECT_EQ(j["failed_plans"], 0);
  EXPECT_GT(j["wall_seconds"].get<double>(), 0);
  ASSERT_TRUE(j["methods"].contains("clips"));
  const auto& clips = j["methods"]["clips"];
  double p = clips["p_true_goal"]["mean"].get<double>();
  EXPECT_GE(p, 0);
  EXPECT_LE(p, 1);
  EXPECT_GE(clips["p_true_goal"]["se"].get<double>(), 0);
  for (const char* m : {"assist_precision", "assist_recall", "goal_success"}) {
    double v = clips[m]["mean"].get<double>();
    EXPECT_GE(v, 0) << m;
    EXPECT_LE(v, 1) << m;
  }
  EXPECT_NEAR(clips["rel_plan_length"]["mean"].get<double>(), 1.0, 1e-9);
  EXPECT_FALSE(j["methods"].contains("multimodal"));  // no endpoint configured
  // The table says the multimodal baseline was skipped.
  EXPECT_NE(result_->out.find("skipped: no chat endpoint"), std::string::npos) << result_->out;
  // Per-step latency (issue 43): every observed step of the four plans, their
  // first steps, the CLIPS decisions; in the table too.
  ASSERT_TRUE(j.contains("latency"));
  const auto& lat = j["latency"];
  EXPECT_GE(lat["inference_threads"].get<int>(), 1);
  EXPECT_GT(lat["belief_step"]["steps"].get<int>(), 0);
  EXPECT_EQ(lat["belief_step"]["steps"], lat["belief_step_one_thread"]["steps"]);
  EXPECT_EQ(lat["belief_start"]["plans"], kPlans.size());
  EXPECT_EQ(lat["decision_method"], "clips");
  EXPECT_GT(lat["assistance_decision"]["decisions"].get<int>(), 0);
  for (const char* k : {"belief_step", "belief_step_one_thread", "belief_start", "assistance_decision"}) {
    const auto& l = lat[k];
    EXPECT_LE(l["median_ms"].get<double>(), l["p95_ms"].get<double>()) << k;
    EXPECT_LE(l["p95_ms"].get<double>(), l["max_ms"].get<double>()) << k;
  }
  EXPECT_NE(result_->out.find("latency: belief step median"), std::string::npos) << result_->out;
  EXPECT_NE(result_->out.find("latency: assistance decision (clips)"), std::string::npos) << result_->out;
  // Where the time went: inference and every method that ran, and the longest run.
  const auto& sec = lat["seconds"];
  EXPECT_GT(sec["inference"].get<double>(), 0);
  ASSERT_TRUE(sec["methods"].contains("clips")) << sec.dump();
  double longest = 0;
  for (const auto& [m, v] : sec["methods"].items()) {
    EXPECT_GE(v.get<double>(), 0) << m;
    longest = std::max(longest, v.get<double>());
  }
  EXPECT_GT(sec["longest_run"]["seconds"].get<double>(), 0);
  EXPECT_LE(sec["longest_run"]["seconds"].get<double>(), longest + 1e-9);
  EXPECT_TRUE(sec["methods"].contains(sec["longest_run"]["method"].get<std::string>())) << sec.dump();
  EXPECT_NE(result_->out.find("time: inference "), std::string::npos) << result_->out;
}

TEST_F(BenchReportTest, ResultsCsvHasOneRowPerPlanAndMethod) {
  ASSERT_EQ(result_->status, 0) << result_->out;
  std::istringstream in(testing::read_text(tmp_->path / "results.csv"));
  std::string line;
  std::getline(in, line);
  EXPECT_EQ(line.rfind("plan,method,", 0), 0u);
  std::set<std::pair<std::string, std::string>> rows;
  int n = 0;
  while (std::getline(in, line)) {
    if (line.empty()) continue;
    auto c1 = line.find(',');
    auto c2 = line.find(',', c1 + 1);
    rows.insert({line.substr(0, c1), line.substr(c1 + 1, c2 - c1 - 1)});
    ++n;
  }
  const std::vector<std::string> methods = {"clips", "lang_only", "action_only", "literal_efficient", "literal_naive"};
  EXPECT_EQ(n, static_cast<int>(kPlans.size() * methods.size()));
  for (auto& p : kPlans)
    for (auto& m : methods) EXPECT_TRUE(rows.count({p, m})) << p << " " << m;
}

TEST_F(BenchReportTest, ReportFilesAndHtml) {
  ASSERT_EQ(result_->status, 0) << result_->out;
  fs::path dir = tmp_->path / "report";
  std::string html = testing::read_text(dir / "report.html");
  ASSERT_FALSE(html.empty());
  EXPECT_NE(html.find("<table class=\"results\">"), std::string::npos);
  // The repo's examples are not the paper's dataset: no "paper" column beside them.
  EXPECT_EQ(html.find("<th>paper</th>"), std::string::npos);
  EXPECT_NE(html.find("skipped: no chat endpoint"), std::string::npos);
  // Offline: no remote resources or scripts.
  for (const char* remote : {"src=\"http", "href=\"http", "url(http", "@import", "src=\"//", "href=\"//"})
    EXPECT_EQ(html.find(remote), std::string::npos) << remote;
  EXPECT_EQ(html.find("<script"), std::string::npos);
  EXPECT_EQ(html.find("<link"), std::string::npos);
  for (auto& p : kPlans) {
    EXPECT_TRUE(fs::exists(dir / "plans" / (p + ".gif"))) << p;
    EXPECT_GT(fs::file_size(dir / "plans" / (p + ".gif")), 1000u) << p;
    EXPECT_TRUE(fs::exists(dir / "plans" / (p + "_posterior.svg"))) << p;
    EXPECT_NE(html.find("href=\"plans/" + p + ".gif\""), std::string::npos) << p;
    EXPECT_NE(html.find("plans/" + p + "_posterior.svg"), std::string::npos) << p;
  }
  // Inline SVG charts: five metric charts, one posterior plot per plan, and a
  // reliability diagram per method with a goal posterior (the examples have no
  // dev/test split, so one each: clips, lang_only, action_only).
  size_t svgs = 0;
  for (size_t at = html.find("<svg"); at != std::string::npos; at = html.find("<svg", at + 1)) ++svgs;
  EXPECT_EQ(svgs, 5 + kPlans.size() + 3);
  EXPECT_NE(html.find("Calibration of the goal posterior"), std::string::npos);
}

}  // namespace report_test

}  // namespace clips::report
