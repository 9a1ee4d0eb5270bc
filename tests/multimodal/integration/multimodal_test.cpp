#include "multimodal/multimodal_test.hpp"

namespace clips::multimodal {
namespace multimodal_test {
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

}  // namespace multimodal_test

}  // namespace clips::multimodal
