// `clips infer --explain`: per-hypothesis utterance likelihoods, their most
// probable commands and rolled-out plans, as text and as JSON.
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include "eval/support.hpp"

namespace clips::eval {
namespace {

using testing::clips_binary;
using testing::examples_dkg;

TEST(InferCli, ExplainJsonListsCommandsAndRollouts) {
  auto r = testing::run(clips_binary() + " infer --dataset " + examples_dkg() +
                        " --plan e1.1.keys --explain --top 2 --json");
  ASSERT_EQ(r.status, 0) << r.out;
  auto j = nlohmann::json::parse(r.out);
  ASSERT_TRUE(j.contains("rollouts"));
  EXPECT_EQ(j["rollouts"].size(), 8u);  // 4 gems x 2 cost profiles
  const nlohmann::json* utt = nullptr;
  for (const auto& st : j["steps"])
    if (st.contains("utterances")) utt = &st["utterances"];
  ASSERT_NE(utt, nullptr);
  ASSERT_EQ(utt->size(), 1u);
  const auto& hs = (*utt)[0]["hypotheses"];
  ASSERT_EQ(hs.size(), 8u);
  double best = -1e300;
  std::string best_h;
  for (const auto& h : hs) {
    const auto& cs = h["commands"];
    EXPECT_LE(cs.size(), 2u);
    for (size_t i = 1; i < cs.size(); ++i) EXPECT_GE(cs[i - 1]["posterior"], cs[i]["posterior"]);
    if (h["log_likelihood"].get<double>() > best) best = h["log_likelihood"], best_h = h["hypothesis"];
    EXPECT_FALSE(j["rollouts"][h["hypothesis"].get<std::string>()].empty());
  }
  // "Can you get me the yellow key?": a yellow-key goal explains it best.
  bool yellow = false;
  for (const auto& h : hs)
    if (h["hypothesis"] == best_h && !h["commands"].empty())
      yellow = h["commands"][0]["command"].get<std::string>().find("yellow") != std::string::npos;
  EXPECT_TRUE(yellow) << best_h;
}

TEST(InferCli, ExplainTextNamesEveryHypothesis) {
  auto r = testing::run(clips_binary() + " infer --dataset " + examples_dkg() + " --plan e1.1.keys --explain");
  ASSERT_EQ(r.status, 0) << r.out;
  for (const char* h : {"gem1/C3", "gem2/C4", "gem4/C3"}) EXPECT_NE(r.out.find(h), std::string::npos) << h;
  EXPECT_NE(r.out.find("rolled-out joint plans"), std::string::npos);
}

TEST(InferCli, SearchesCutOffByTheBudgetAreReported) {
  // The default budget suffices on the example plan: nothing to report.
  auto ok = testing::run("{ " + clips_binary() + " infer --dataset " + examples_dkg() +
                         " --plan e1.1.keys --json 2>/dev/null; }");
  ASSERT_EQ(ok.status, 0) << ok.out;
  EXPECT_EQ(nlohmann::json::parse(ok.out)["searches_stopped_by_budget"], 0);
  auto quiet = testing::run(clips_binary() + " infer --dataset " + examples_dkg() + " --plan e1.1.keys");
  EXPECT_EQ(quiet.out.find("note:"), std::string::npos) << quiet.out;
  // A tiny budget cuts searches off: the JSON counts them and stderr says so.
  auto cut = testing::run("{ " + clips_binary() + " infer --dataset " + examples_dkg() +
                          " --plan e1.1.keys --max-nodes 20 --json 2>/dev/null; }");
  ASSERT_EQ(cut.status, 0) << cut.out;
  EXPECT_GT(nlohmann::json::parse(cut.out)["searches_stopped_by_budget"].get<int>(), 0);
  auto note = testing::run(clips_binary() + " infer --dataset " + examples_dkg() + " --plan e1.1.keys --max-nodes 20");
  EXPECT_NE(note.out.find("stopped at the budget of 20 expansions"), std::string::npos) << note.out;
}

TEST(InferCli, BadTopIsRejected) {
  auto r = testing::run(clips_binary() + " infer --dataset " + examples_dkg() + " --plan e1.1.keys --explain --top -1");
  EXPECT_NE(r.status, 0);
}

}  // namespace
}  // namespace clips::eval
