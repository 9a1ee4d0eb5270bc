// Utterances the model cannot read carry little evidence, and the user is
// told: `clips infer --json` on a copy of an example plan whose instruction is
// replaced by text in another language, punctuation only, or 100 kB of text.
// The posterior must stay near what the actions alone say (never jump to one
// goal, never fall back to the prior), with a warning on stderr and in JSON.
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "eval/support.hpp"

namespace clips::eval {
namespace {

namespace fs = std::filesystem;
using testing::clips_binary;
using testing::contains;
using testing::run;

// e1.1.keys of the examples, with its "; <utterance>" line replaced.
struct PlanWithUtterance : testing::ExamplesCopy {
  explicit PlanWithUtterance(const std::string& utterance) : ExamplesCopy("utterance") {
    const fs::path plan = file("plans/observed/e1.1.keys.pddl");
    std::string text = testing::read_text(plan), out;
    size_t start = 0;
    while (start < text.size()) {
      size_t end = text.find('\n', start);
      if (end == std::string::npos) end = text.size();
      const std::string line = text.substr(start, end - start);
      out += (line.rfind(";", 0) == 0 ? "; " + utterance : line) + "\n";
      start = end + 1;
    }
    std::ofstream(plan, std::ios::binary) << out;
    fs::remove(fs::path(ds) / "stimuli.json");  // its utterances would no longer match
  }
};

struct Inferred {
  int status = -1;
  std::string stderr_text;
  nlohmann::json json;
};

Inferred infer(const std::string& ds, const std::string& modality) {
  Inferred r;
  testing::TempDir err{"stderr"};
  const std::string err_file = (err.path / "err.txt").string();
  // run() adds 2>&1; the group keeps stderr in its own file, so stdout is the JSON alone.
  auto out = run("{ " + clips_binary() + " infer --dataset " + ds + " --plan e1.1.keys --json --modalities " +
                 modality + " 2>" + err_file + "; }");
  r.status = out.status;
  r.stderr_text = testing::read_text(err_file);
  r.json = nlohmann::json::parse(out.out, nullptr, false);
  return r;
}

std::vector<double> final_posterior(const nlohmann::json& j) {
  return testing::goal_probabilities(j["steps"].back()["posterior"]);
}

double max_abs_diff(const std::vector<double>& a, const std::vector<double>& b) {
  double d = 0;
  for (size_t i = 0; i < a.size(); ++i) d = std::max(d, std::abs(a[i] - b[i]));
  return d;
}

// Runs both modalities; returns the largest change the utterance made to the
// final goal posterior (against actions alone).
double utterance_effect(const PlanWithUtterance& p, Inferred& both) {
  both = infer(p.ds, "both");
  Inferred action = infer(p.ds, "action");
  EXPECT_EQ(both.status, 0) << both.stderr_text;
  EXPECT_EQ(action.status, 0) << action.stderr_text;
  if (both.json.is_discarded() || action.json.is_discarded()) {
    ADD_FAILURE() << "no JSON: " << both.stderr_text;
    return 1;
  }
  const auto pb = final_posterior(both.json), pa = final_posterior(action.json);
  EXPECT_EQ(pb.size(), pa.size());
  double sum = 0;
  for (double x : pb) {
    EXPECT_TRUE(std::isfinite(x));
    sum += x;
  }
  EXPECT_NEAR(sum, 1.0, 1e-9);
  return max_abs_diff(pb, pa);
}

TEST(UnreadableUtterance, ReadableInstructionStillCountsInFull) {
  PlanWithUtterance p("Can you get me the yellow key?");
  Inferred both;
  const double effect = utterance_effect(p, both);
  EXPECT_GT(effect, 0.05);  // it is evidence
  EXPECT_TRUE(both.json["utterance_warnings"].empty()) << both.json["utterance_warnings"];
  EXPECT_FALSE(contains(both.stderr_text, "warning")) << both.stderr_text;
}

TEST(UnreadableUtterance, AnotherLanguageCarriesLittleEvidence) {
  PlanWithUtterance p("Kannst du mir den roten Schlüssel geben?");
  Inferred both;
  const double effect = utterance_effect(p, both);
  EXPECT_LT(effect, 0.05);
  const std::vector<double> post = final_posterior(both.json);
  EXPECT_LT(*std::max_element(post.begin(), post.end()), 0.99);
  ASSERT_EQ(both.json["utterance_warnings"].size(), 1u) << both.json.dump();
  EXPECT_TRUE(contains(both.json["utterance_warnings"][0], "Kannst du mir")) << both.json["utterance_warnings"];
  EXPECT_TRUE(contains(both.stderr_text, "warning: utterance \"Kannst du mir")) << both.stderr_text;
}

TEST(UnreadableUtterance, PunctuationOnlyIsIgnored) {
  PlanWithUtterance p("?!?! ... ?");
  Inferred both;
  EXPECT_LT(utterance_effect(p, both), 1e-9);
  ASSERT_EQ(both.json["utterance_warnings"].size(), 1u) << both.json.dump();
  EXPECT_TRUE(contains(both.json["utterance_warnings"][0], "has no words")) << both.json["utterance_warnings"];
  EXPECT_TRUE(contains(both.stderr_text, "ignored")) << both.stderr_text;
}

// 100 kB: every likelihood underflows; the posterior is what the actions say,
// not the prior.
TEST(UnreadableUtterance, HundredKilobyteUtteranceDoesNotResetThePosterior) {
  std::string huge;
  while (huge.size() < 100000) huge += "can you pass me the red key and ";
  huge += "thanks";
  PlanWithUtterance p(huge);
  Inferred both;
  EXPECT_LT(utterance_effect(p, both), 0.05);
  ASSERT_EQ(both.json["utterance_warnings"].size(), 1u) << both.stderr_text;
  EXPECT_TRUE(contains(both.stderr_text, "warning: utterance")) << both.stderr_text;
  EXPECT_TRUE(contains(both.stderr_text, "bytes)")) << both.stderr_text;  // quoted short, with its size
}

}  // namespace
}  // namespace clips::eval
