// `clips serve` as a process on 127.0.0.1: the HTTP front end, its body
// limit, and SIGTERM letting an in-flight request finish before exit 0.
#include <gtest/gtest.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <cstdio>
#include <regex>
#include <string>
#include <thread>

#include <httplib.h>
#include <nlohmann/json.hpp>

#include "serve/kitchen_folder.hpp"
#include "serve/server_process.hpp"

namespace {

using nlohmann::json;

using clips::serve::testing::ServerProcess;

TEST(ServeLoopback, AnswersJsonAndLimitsBodies) {
  ServerProcess server;
  ASSERT_GT(server.port, 0);
  httplib::Client cli("127.0.0.1", server.port);
  cli.set_read_timeout(60, 0);
  auto r = cli.Get("/api/datasets");
  ASSERT_TRUE(r);
  EXPECT_EQ(r->status, 200);
  EXPECT_EQ(json::parse(r->body)["datasets"][0]["name"], "doors-keys-gems");
  r = cli.Get("/");
  ASSERT_TRUE(r);
  EXPECT_EQ(r->status, 200);
  EXPECT_NE(r->get_header_value("Content-Type").find("text/html"), std::string::npos);

  r = cli.Post("/api/sessions", json{{"dataset", "doors-keys-gems"}, {"problem", std::string(2000, 'x')}}.dump(),
               "application/json");
  ASSERT_TRUE(r);
  EXPECT_EQ(r->status, 413);
  EXPECT_NE(json::parse(r->body)["error"].get<std::string>().find("1024"), std::string::npos);

  r = cli.Post("/api/sessions", R"j({"dataset":"doors-keys-gems","problem":"e1"})j", "application/json");
  ASSERT_TRUE(r);
  ASSERT_EQ(r->status, 201);
  const std::string id = json::parse(r->body)["id"];
  r = cli.Post(("/api/sessions/" + id + "/act").c_str(), R"j({"action":"(right robot)"})j", "application/json");
  ASSERT_TRUE(r);
  EXPECT_EQ(r->status, 409);
  r = cli.Delete(("/api/sessions/" + id).c_str());
  ASSERT_TRUE(r);
  EXPECT_EQ(r->status, 200);
  EXPECT_EQ(cli.Get(("/api/sessions/" + id).c_str())->status, 404);
  EXPECT_EQ(server.stop(), 0);
}

TEST(ServeLoopback, SigtermFinishesTheRequestInFlightAndExitsZero) {
  // Without the model cache the first instruction trains the embedded model
  // (about a second): a request still running when the signal comes.
  ServerProcess server({"CLIPS_LM_CACHE_DIR=off"});
  ASSERT_GT(server.port, 0);
  httplib::Client cli("127.0.0.1", server.port);
  cli.set_read_timeout(120, 0);
  auto r = cli.Post("/api/sessions", R"j({"dataset":"doors-keys-gems","problem":"e1"})j", "application/json");
  ASSERT_TRUE(r);
  ASSERT_EQ(r->status, 201);
  const std::string id = json::parse(r->body)["id"];
  int heard_status = -1;  // -1: no reply at all
  std::thread slow([&] {
    httplib::Client c2("127.0.0.1", server.port);
    c2.set_read_timeout(120, 0);
    auto res = c2.Post(("/api/sessions/" + id + "/hear").c_str(), R"j({"utterance":"Can you get me the yellow key?"})j",
                       "application/json");
    if (res) heard_status = res->status;
  });
  std::this_thread::sleep_for(std::chrono::milliseconds(300));
  const auto t0 = std::chrono::steady_clock::now();
  const int code = server.stop();
  slow.join();
  EXPECT_EQ(code, 0);
  EXPECT_EQ(heard_status, 200) << "the request in flight was dropped (-1) or failed";
  EXPECT_LT(std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count(), 60.0);
}

// POSTs a JSON body and returns (status, reply); status -1 when no reply came.
std::pair<int, json> post(httplib::Client& cli, const std::string& path, const json& body) {
  auto r = cli.Post(path.c_str(), body.dump(), "application/json");
  if (!r) return {-1, json()};
  return {r->status, json::parse(r->body)};
}

bool has_action(const json& state, const std::string& action) {
  for (const auto& a : state["actions"])
    if (a == action) return true;
  return false;
}

// Over HTTP: the workshop (scene "text") and the kitchen of docs/domains.md
// from a folder without any plan file; a few moves, an instruction, the
// assistant answering.
TEST(ServeLoopback, PlaysTextScenePacksAndProblemsWithoutPlans) {
  clips::serve::testing::KitchenFolder kitchen;
  ServerProcess server({}, {"--dataset", std::string(CLIPS_SOURCE_DIR) + "/data/datasets/workshop", "--dataset",
                            kitchen.dir, "--assist-nodes", "20000"});
  ASSERT_GT(server.port, 0);
  httplib::Client cli("127.0.0.1", server.port);
  cli.set_read_timeout(120, 0);
  auto r = cli.Get("/api/datasets");
  ASSERT_TRUE(r);
  const json catalogue = json::parse(r->body);
  ASSERT_EQ(catalogue["datasets"].size(), 2u);
  EXPECT_EQ(catalogue["datasets"][1]["name"], "workshop");
  EXPECT_EQ(catalogue["datasets"][1]["scene"], "text");
  EXPECT_EQ(catalogue["datasets"][0]["problems"][1],
            json({{"id", "2"}, {"plans", json::array()}, {"goals", {"cake", "cookies", "fudge", "pudding"}}}));

  auto [status, st] = post(cli, "/api/sessions", {{"dataset", "workshop"}, {"problem", "2"}});
  ASSERT_EQ(status, 201) << st.dump();
  std::string url = "/api/sessions/" + st["id"].get<std::string>();
  EXPECT_EQ(st["scene"]["kind"], "text");
  ASSERT_TRUE(has_action(st, "(pickup human panel1 rack)")) << st["actions"].dump();
  std::tie(status, st) = post(cli, url + "/act", {{"action", "(pickup human panel1 rack)"}});
  ASSERT_EQ(status, 200) << st.dump();
  std::tie(status, st) = post(cli, url + "/assist", {{"apply", true}});
  ASSERT_EQ(status, 200) << st.dump();
  std::tie(status, st) = post(cli, url + "/hear", {{"utterance", "Could you bring the wooden one to the bench?"}});
  ASSERT_EQ(status, 200) << st.dump();
  EXPECT_FALSE(st["reading"]["commands"].empty());
  std::tie(status, st) = post(cli, url + "/act", {{"action", "(wait human)"}});
  ASSERT_EQ(status, 200) << st.dump();
  std::tie(status, st) = post(cli, url + "/assist", {{"apply", true}});
  ASSERT_EQ(status, 200) << st.dump();
  EXPECT_NE(st["decision"]["action"].get<std::string>().find("robot"), std::string::npos);

  std::tie(status, st) = post(cli, "/api/sessions", {{"dataset", "kitchen"}, {"problem", "2"}});
  ASSERT_EQ(status, 201) << st.dump();
  url = "/api/sessions/" + st["id"].get<std::string>();
  EXPECT_TRUE(st["plan"].is_null());
  EXPECT_EQ(st["scene"]["kind"], "text");
  std::tie(status, st) = post(cli, url + "/hear", {{"utterance", "Can you fetch the butter?"}});
  ASSERT_EQ(status, 200) << st.dump();
  std::tie(status, st) = post(cli, url + "/act", {{"action", "(move cook counter pantry)"}});
  ASSERT_EQ(status, 200) << st.dump();
  std::tie(status, st) = post(cli, url + "/assist", {{"apply", true}});
  ASSERT_EQ(status, 200) << st.dump();
  EXPECT_EQ(st["state"]["turn"], "cook");
  std::tie(status, st) = post(cli, "/api/sessions", {{"dataset", "kitchen"}, {"problem", "../kitchen/problems/2"}});
  EXPECT_EQ(status, 400);
  EXPECT_EQ(server.stop(), 0);
}

// Over HTTP: a session from the domain and problem as PDDL text, with the
// pack as JSON; malformed text is a 400 naming the field.
TEST(ServeLoopback, SessionFromPddlText) {
  ServerProcess server({}, {"--dataset", std::string(CLIPS_SOURCE_DIR) + "/data/examples/doors-keys-gems",
                            "--max-pddl-bytes", "8000"});
  ASSERT_GT(server.port, 0);
  httplib::Client cli("127.0.0.1", server.port);
  cli.set_read_timeout(120, 0);
  const auto files = clips::serve::testing::docs_example_files();
  json pack = json::parse(files.at("kitchen/pack.json"));
  pack.erase("fewshot");
  const json request = {{"domain", files.at("kitchen/domain.pddl")}, {"problem", clips::serve::testing::kitchen_problem_2()},
                        {"pack", pack}};
  auto [status, st] = post(cli, "/api/sessions", request);
  ASSERT_EQ(status, 201) << st.dump();
  const std::string url = "/api/sessions/" + st["id"].get<std::string>();
  EXPECT_TRUE(st["dataset"].is_null());
  EXPECT_EQ(st["problem"], "kitchen-2");
  std::tie(status, st) = post(cli, url + "/act", {{"action", "(move cook counter pantry)"}});
  ASSERT_EQ(status, 200) << st.dump();
  std::tie(status, st) = post(cli, url + "/hear", {{"utterance", "Could you get the cold milk?"}});
  ASSERT_EQ(status, 200) << st.dump();
  std::tie(status, st) = post(cli, url + "/assist", {{"apply", true}});
  ASSERT_EQ(status, 200) << st.dump();
  EXPECT_EQ(st["state"]["t"], 2);

  json bad = request;
  bad["domain"] = "(define (domain kitchen) (:predicates (at ?a - nowhere)))";
  std::tie(status, st) = post(cli, "/api/sessions", bad);
  EXPECT_EQ(status, 400);
  EXPECT_NE(st["error"].get<std::string>().find("field 'domain'"), std::string::npos) << st.dump();
  bad = request;
  bad["problem"] = std::string(8001, ' ');
  std::tie(status, st) = post(cli, "/api/sessions", bad);
  EXPECT_EQ(status, 400);
  EXPECT_NE(st["error"].get<std::string>().find("field 'problem'"), std::string::npos) << st.dump();
  EXPECT_EQ(server.stop(), 0);
}

}  // namespace
