#include "serve/service_test.hpp"

namespace clips::serve {
namespace service_test {
TEST_F(Fixture, PlayHearAssistUndoResetAndSwitchMethod) {
  auto s = make();
  const std::string id = create(*s);
  const std::string url = "/api/sessions/" + id;
  for (int k = 0; k < 2; ++k) {
    ASSERT_EQ(s->handle("POST", url + "/act", R"j({"action":"(left human)"})j").status, 200);
    Reply r = s->handle("POST", url + "/assist", R"j({"apply":true})j");
    ASSERT_EQ(r.status, 200) << r.body;
    json d = body(r)["decision"];
    EXPECT_FALSE(d["candidates"].empty());
    EXPECT_EQ(body(r)["state"]["turn"], "human");
  }
  Reply r = s->handle("POST", url + "/hear", R"j({"utterance":"Can you get me the yellow key?"})j");
  ASSERT_EQ(r.status, 200) << r.body;
  json st = body(r);
  ASSERT_FALSE(st["reading"].is_null());
  ASSERT_FALSE(st["reading"]["commands"].empty());
  EXPECT_NE(st["reading"]["commands"][0]["command"].get<std::string>().find("yellow"), std::string::npos);
  EXPECT_EQ(st["history"].size(), 6u);  // start, 4 actions, the utterance
  EXPECT_EQ(st["t"], 4);
  // The instruction moves the belief: the trace has one more point.
  EXPECT_EQ(body(s->handle("GET", url + "/trace", ""))["steps"].size(), 6u);

  r = s->handle("POST", url + "/method", R"j({"method":"literal"})j");
  ASSERT_EQ(r.status, 200);
  EXPECT_EQ(body(r)["reading"]["source"].get<std::string>().rfind("literal", 0), 0u);
  ASSERT_EQ(s->handle("POST", url + "/act", R"j({"action":"(wait human)"})j").status, 200);
  r = s->handle("POST", url + "/assist", R"j({"apply":false})j");
  ASSERT_EQ(r.status, 200) << r.body;
  EXPECT_TRUE(body(r)["decision"].contains("command"));
  EXPECT_EQ(body(r)["state"]["turn"], "robot");  // not applied

  r = s->handle("POST", url + "/undo", "");
  ASSERT_EQ(r.status, 200);
  EXPECT_EQ(body(r)["t"], 4);  // the (wait human) is taken back, the instruction before it stays
  EXPECT_FALSE(body(r)["reading"].is_null());
  r = s->handle("POST", url + "/undo", "");
  EXPECT_EQ(body(r)["t"], 4);  // the instruction goes alone: the move before it stays
  EXPECT_TRUE(body(r)["reading"].is_null());
  r = s->handle("POST", url + "/undo", "");
  EXPECT_EQ(body(r)["t"], 2);  // back before the second (left human) and its reply
  r = s->handle("POST", url + "/reset", "{}");
  ASSERT_EQ(r.status, 200);
  EXPECT_EQ(body(r)["t"], 0);
  EXPECT_EQ(s->handle("POST", url + "/undo", "").status, 409);
  EXPECT_EQ(s->handle("POST", url + "/method", R"j({"method":"oracle"})j").status, 400);
}

TEST_F(Fixture, SessionsRunInParallelAndIndependently) {
  auto s = make();
  auto play = [&](const std::string& id, std::string& out) {
    const std::string url = "/api/sessions/" + id;
    for (int k = 0; k < 2; ++k) {
      s->handle("POST", url + "/act", R"j({"action":"(left human)"})j");
      s->handle("POST", url + "/assist", R"j({"apply":true})j");
    }
    s->handle("POST", url + "/hear", R"j({"utterance":"Can you get me the yellow key?"})j");
    out = body(s->handle("GET", url + "/posterior", "")).dump();
  };
  const std::string a = create(*s), b = create(*s), c = create(*s);
  std::string ra, rb, rc;
  std::thread ta(play, a, std::ref(ra)), tb(play, b, std::ref(rb));
  ta.join();
  tb.join();
  play(c, rc);
  EXPECT_EQ(ra, rc);
  EXPECT_EQ(rb, rc);
  // One session hammered from two threads: requests are serialised, none lost.
  std::thread t1([&] { for (int i = 0; i < 20; ++i) s->handle("GET", "/api/sessions/" + a, ""); });
  std::thread t2([&] { s->handle("POST", "/api/sessions/" + a + "/reset", ""); });
  t1.join();
  t2.join();
  EXPECT_EQ(body(s->handle("GET", "/api/sessions/" + a, ""))["t"], 0);
}

}  // namespace service_test

}  // namespace clips::serve
