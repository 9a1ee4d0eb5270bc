// The multimodal-LLM baseline against the loopback fake chat server.
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include "eval/experiment.hpp"
#include "multimodal/multimodal.hpp"
#include "eval/support.hpp"
#include "language/listener.hpp"
#include "lm/fake_openai_server.hpp"

namespace clips::eval {
namespace {

using lm::fake::FakeFaults;
using lm::fake::FakeOpenAiServer;
using lm::fake::FakeReply;
using nlohmann::json;

const std::vector<std::string> kGoals = {"gem1", "gem2", "gem3", "gem4"};

// ---- parsing -------------------------------------------------------------------

TEST(MultimodalParse, StrictJson) {
  auto a = parse_multimodal_answer(
      R"J({"goal_probabilities": {"gem1": 0.1, "gem2": 0.1, "gem3": 0.7, "gem4": 0.1}, "actions": ["(down robot)"]})J",
      kGoals);
  EXPECT_NEAR(a.goal_posterior[2], 0.7, 1e-12);
  ASSERT_EQ(a.actions.size(), 1u);
  EXPECT_EQ(a.actions[0], "(down robot)");
  EXPECT_TRUE(a.notes.empty());
}

TEST(MultimodalParse, FencedJsonMissingGoalsAndRenormalisation) {
  auto a = parse_multimodal_answer("```json\n{\"goal_probabilities\": {\"gem3\": 2e-1, \"gem1\": 0.2}, \"actions\": []}\n```",
                                   kGoals);
  EXPECT_NEAR(a.goal_posterior[0], 0.5, 1e-12);
  EXPECT_NEAR(a.goal_posterior[2], 0.5, 1e-12);
  EXPECT_EQ(a.goal_posterior[1], 0);
  EXPECT_EQ(a.notes.size(), 3u);  // gem2, gem4 missing; renormalised
}

void expect_error(const std::string& text, const std::string& fragment) {
  try {
    parse_multimodal_answer(text, kGoals);
    ADD_FAILURE() << "no error for " << text;
  } catch (const MultimodalError& e) {
    EXPECT_NE(std::string(e.what()).find(fragment), std::string::npos) << e.what();
  }
}

TEST(MultimodalParse, ErrorsNameTheField) {
  expect_error("Sure! The goal is gem3.", "not valid JSON");
  expect_error("[1, 2]", "not an object");
  expect_error(R"J({"actions": []})J", "\"goal_probabilities\"");
  expect_error(R"J({"goal_probabilities": [0.5, 0.5], "actions": []})J", "must be an object");
  expect_error(R"J({"goal_probabilities": {"gem9": 1}, "actions": []})J", "unknown goal \"gem9\"");
  expect_error(R"J({"goal_probabilities": {"gem1": "high"}, "actions": []})J", "\"goal_probabilities\".gem1 must be a number");
  expect_error(R"J({"goal_probabilities": {"gem1": 1.5}, "actions": []})J", "in [0, 1]");
  expect_error(R"J({"goal_probabilities": {"gem1": 0}, "actions": []})J", "sum to 0");
  expect_error(R"J({"goal_probabilities": {"gem1": 1}})J", "no \"actions\" field");
  expect_error(R"J({"goal_probabilities": {"gem1": 1}, "actions": "(down robot)"})J", "\"actions\" must be an array");
  expect_error(R"J({"goal_probabilities": {"gem1": 1}, "actions": [3]})J", "\"actions\"[0] must be a string");
}

// ---- end to end against the fake server ---------------------------------------

class MultimodalServer : public ::testing::Test {
 protected:
  void SetUp() override {
    server_.start();
    ds_ = std::make_unique<data::Dataset>(data::Dataset::load(testing::examples_dkg()));
    lm_ = language::make_language_model("embedded", {});
  }
  void answer(const json& j) {
    std::string text = j.dump();
    server_.set_chat_rule([text](const json&) { return text; });
  }
  ExperimentOptions options(int max_retries = 2) {
    ExperimentOptions eo;
    eo.methods = {"clips", "multimodal"};
    eo.multimodal.base_url = server_.base_url();
    eo.multimodal.model = "fake-vision";
    eo.multimodal.api_key = "";
    eo.multimodal.http.max_retries = max_retries;
    eo.multimodal.http.backoff_initial = std::chrono::milliseconds(5);
    eo.multimodal.http.total_timeout = std::chrono::milliseconds(2000);
    return eo;
  }
  const MethodResult& run(const std::string& plan, const ExperimentOptions& eo) {
    outcome_ = evaluate_plan(*ds_, ds_->plan(plan), *lm_, eo);
    EXPECT_TRUE(outcome_.error.empty()) << outcome_.error;
    const MethodResult* r = outcome_.find("multimodal");
    EXPECT_NE(r, nullptr);
    return *r;
  }
  FakeOpenAiServer server_;
  std::unique_ptr<data::Dataset> ds_;
  std::shared_ptr<lm::LanguageModel> lm_;
  PlanOutcome outcome_;
};

const json kGoodAnswer = {{"goal_probabilities", {{"gem1", 0.1}, {"gem2", 0.05}, {"gem3", 0.8}, {"gem4", 0.05}}},
                          {"actions", {"(down robot)", "(pickup robot key3)", "(handover robot human key3)"}}};

TEST_F(MultimodalServer, EndToEndOnAnExamplePlan) {
  answer(kGoodAnswer);
  const MethodResult& r = run("e1.1.keys", options());
  ASSERT_TRUE(r.error.empty()) << r.error;
  ASSERT_TRUE(r.p_true_goal.has_value());
  EXPECT_NEAR(*r.p_true_goal, 0.8, 1e-9);  // true goal: gem3
  EXPECT_EQ(r.options.count("key3"), 1u) << "the robot fetched the yellow key";
  EXPECT_DOUBLE_EQ(r.precision, 1.0);
  EXPECT_DOUBLE_EQ(r.recall, 1.0);
  EXPECT_DOUBLE_EQ(r.goal_success, 1.0);
  EXPECT_TRUE(r.notes.empty());
  EXPECT_NE(std::find(r.plan.begin(), r.plan.end(), "(handover robot human key3)"), r.plan.end());
  EXPECT_GT(r.rel_plan_length, 0);
  // What was sent: the rules, the utterance, the goals and a PNG picture.
  json body = server_.last_chat_body();
  EXPECT_EQ(body["model"], "fake-vision");
  std::string text;
  int images = 0;
  for (auto& m : body["messages"])
    if (m["content"].is_array())
      for (auto& part : m["content"]) {
        if (part["type"] == "text") text += part["text"].get<std::string>();
        if (part["type"] == "image_url") {
          ++images;
          EXPECT_EQ(part["image_url"]["url"].get<std::string>().rfind("data:image/png;base64,", 0), 0u);
        }
      }
  EXPECT_EQ(images, 1);
  EXPECT_NE(text.find("Can you get me the yellow key?"), std::string::npos);
  EXPECT_NE(text.find("gem4"), std::string::npos);
  EXPECT_NE(text.find("(pickup A I)"), std::string::npos);
  EXPECT_NE(text.find("goal_probabilities"), std::string::npos);
}

TEST_F(MultimodalServer, IllegalAndUnknownActionsAreReportedAndSkipped) {
  json a = kGoodAnswer;
  a["actions"] = {"(pickup robot key1)", "(fly robot)", "(left human)", "not an action"};
  answer(a);
  const MethodResult& r = run("e1.1.keys", options());
  ASSERT_TRUE(r.error.empty()) << r.error;
  ASSERT_EQ(r.notes.size(), 4u);
  EXPECT_NE(r.notes[0].find("illegal"), std::string::npos) << r.notes[0];
  EXPECT_NE(r.notes[1].find("not a ground action"), std::string::npos) << r.notes[1];
  EXPECT_NE(r.notes[2].find("not the robot's"), std::string::npos) << r.notes[2];
  EXPECT_NE(r.notes[3].find("not a ground action"), std::string::npos) << r.notes[3];
  EXPECT_TRUE(r.options.empty());
  EXPECT_DOUBLE_EQ(r.recall, 0.0);
  EXPECT_DOUBLE_EQ(r.goal_success, 1.0) << "the human finishes alone";
  // The robot waited on its turns instead (and, its list used up, afterwards too).
  std::vector<std::string> robot;
  for (auto& act : r.plan)
    if (act.find(' ') != std::string::npos && act.substr(act.find(' ') + 1, 5) == "robot") robot.push_back(act);
  ASSERT_GE(robot.size(), 4u);
  for (size_t i = 0; i < 4; ++i) EXPECT_EQ(robot[i], "(wait robot)") << i;
}

TEST_F(MultimodalServer, UnknownGoalIsAMethodError) {
  answer({{"goal_probabilities", {{"gem7", 1.0}}}, {"actions", json::array()}});
  const MethodResult& r = run("e1.1.keys", options());
  EXPECT_NE(r.error.find("unknown goal \"gem7\""), std::string::npos) << r.error;
  EXPECT_NE(outcome_.find("clips"), nullptr);  // the other methods are unaffected
  EXPECT_TRUE(outcome_.find("clips")->error.empty());
}

TEST_F(MultimodalServer, NonJsonAnswer) {
  answer(kGoodAnswer);
  FakeFaults f;
  f.reply = FakeReply::NonJsonAnswer;
  server_.set_faults(f);
  const MethodResult& r = run("e1.1.keys", options());
  EXPECT_NE(r.error.find("not valid JSON"), std::string::npos) << r.error;
}

TEST_F(MultimodalServer, MalformedJsonReply) {
  answer(kGoodAnswer);
  FakeFaults f;
  f.reply = FakeReply::MalformedJson;
  server_.set_faults(f);
  const MethodResult& r = run("e1.1.keys", options());
  EXPECT_FALSE(r.error.empty());
  EXPECT_NE(r.error.find("127.0.0.1"), std::string::npos) << r.error;
}

TEST_F(MultimodalServer, RetriesAfter429And500) {
  answer(kGoodAnswer);
  FakeFaults f;
  f.fail_first = 1;
  f.fail_status = 429;
  f.retry_after = "0";
  server_.set_faults(f);
  const MethodResult& r = run("e1.1.keys", options());
  EXPECT_TRUE(r.error.empty()) << r.error;
  EXPECT_EQ(server_.chat_requests(), 2);
  f.fail_status = 500;
  server_.set_faults(f);
  const MethodResult& r2 = run("e1.1.keys", options());
  EXPECT_TRUE(r2.error.empty()) << r2.error;
  EXPECT_EQ(server_.chat_requests(), 4);
  // More failures than retries: a clear error.
  f.fail_first = 5;
  server_.set_faults(f);
  const MethodResult& r3 = run("e1.1.keys", options(1));
  EXPECT_NE(r3.error.find("500"), std::string::npos) << r3.error;
}

TEST_F(MultimodalServer, Timeout) {
  answer(kGoodAnswer);
  FakeFaults f;
  f.delay_ms = 1500;
  server_.set_faults(f);
  auto eo = options(0);
  eo.multimodal.http.total_timeout = std::chrono::milliseconds(200);
  const MethodResult& r = run("e1.1.keys", eo);
  EXPECT_FALSE(r.error.empty());
  EXPECT_NE(r.error.find("time"), std::string::npos) << r.error;
}

TEST_F(MultimodalServer, AssistAndBenchCli) {
  answer(kGoodAnswer);
  auto a = testing::run(testing::clips_binary() + " assist --dataset " + testing::examples_dkg() +
                        " --plan e1.1.keys --method multimodal --json --chat-base-url " + server_.base_url());
  ASSERT_EQ(a.status, 0) << a.out;
  auto j = json::parse(a.out.substr(a.out.find('{')));
  EXPECT_NEAR(j["p_true_goal"].get<double>(), 0.8, 1e-9);
  EXPECT_EQ(j["assist_options"].count("key3"), 1u);
  testing::TempDir tmp("bench-mm");
  auto b = testing::run(testing::clips_binary() + " bench --dataset " + testing::examples_dkg() +
                        " --plans e1.1.keys --no-progress --out " + tmp.str() + " --chat-base-url " + server_.base_url());
  ASSERT_EQ(b.status, 0) << b.out;
  auto s = json::parse(testing::read_text(tmp.path / "summary.json"));
  ASSERT_TRUE(s["methods"].contains("multimodal")) << s.dump();
  EXPECT_NEAR(s["methods"]["multimodal"]["p_true_goal"]["mean"].get<double>(), 0.8, 1e-9);
  EXPECT_EQ(b.out.find("skipped"), std::string::npos) << b.out;
  auto none = testing::run("env -u CLIPS_CHAT_BASE_URL " + testing::clips_binary() + " bench --dataset " +
                           testing::examples_dkg() + " --plans e1.1.keys --no-progress --methods multimodal");
  EXPECT_NE(none.status, 0);
  EXPECT_NE(none.out.find("needs a chat endpoint"), std::string::npos) << none.out;
}

}  // namespace
}  // namespace clips::eval
