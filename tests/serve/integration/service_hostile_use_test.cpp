// The request handlers of `clips serve` under hostile use (no socket): session ids
// from the OS source, per-client quotas, room made on a full server, JSON
// errors in our own words, a domain without a pack, and a problem too large
// for the planner's tables answered 4xx.
#include <gtest/gtest.h>

#include <atomic>
#include <chrono>
#include <fstream>
#include <set>
#include <sstream>

#include <nlohmann/json.hpp>

#include "language/listener.hpp"
#include "serve/service.hpp"

namespace clips::serve {
namespace {

using nlohmann::json;

const std::string kExamples = std::string(CLIPS_SOURCE_DIR) + "/data/examples/doors-keys-gems";

std::shared_ptr<lm::LanguageModel> shared_lm() {
  static auto lm = language::make_language_model("embedded");
  return lm;
}

std::string read(const std::string& path) {
  std::ifstream in(path);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

struct FakeClock {
  std::atomic<int64_t> seconds{1000};
  Service::Clock::time_point now() const {
    return Service::Clock::time_point(
        std::chrono::duration_cast<Service::Clock::duration>(std::chrono::seconds(seconds.load())));
  }
};

struct ServiceUnderHostileUse : ::testing::Test {
  FakeClock clock;
  std::unique_ptr<Service> make(ServiceLimits limits = {}) {
    return std::make_unique<Service>(std::vector<std::string>{kExamples}, limits, shared_lm(),
                                     [this] { return clock.now(); });
  }
  static json body(const Reply& r) { return json::parse(r.body); }
  static Reply create(Service& s, const std::string& client, bool owner = false) {
    return s.handle(Request{"POST", "/api/sessions", R"j({"dataset":"doors-keys-gems","problem":"e1"})j", owner, client});
  }
  static std::string id_of(const Reply& r) {
    EXPECT_EQ(r.status, 201) << r.body;
    return r.status == 201 ? body(r).value("id", "") : "";
  }
};

TEST_F(ServiceUnderHostileUse, SessionIdsAreTheRandomSourcesBytes) {
  auto s = make();
  // A source that counts: each id must be the next 16 bytes, in hex, and
  // nothing else (no generator of our own between the source and the id).
  auto next = std::make_shared<unsigned>(0);
  s->set_random_source([next](void* out, size_t n) {
    auto* b = static_cast<unsigned char*>(out);
    for (size_t i = 0; i < n; ++i) b[i] = static_cast<unsigned char>((*next)++);
  });
  EXPECT_EQ(id_of(create(*s, "")), "000102030405060708090a0b0c0d0e0f");
  EXPECT_EQ(id_of(create(*s, "")), "101112131415161718191a1b1c1d1e1f");
  EXPECT_EQ(*next, 32u);
}

TEST_F(ServiceUnderHostileUse, TheDefaultSourceIsTheKernels) {
  // The server's ids come from os_random_bytes unless a test replaces it,
  // and os_random_bytes reads getrandom(2), not a generator seeded once.
  const std::string source = read(std::string(CLIPS_SOURCE_DIR) + "/src/serve/service.cpp");
  const std::string header = read(std::string(CLIPS_SOURCE_DIR) + "/src/serve/service.hpp");
  EXPECT_NE(source.find("getrandom(bytes + got, n - got, 0)"), std::string::npos);
  EXPECT_NE(header.find("RandomSource random_ = os_random_bytes;"), std::string::npos);
  for (const char* weak : {"mt19937", "random_device", "rand("}) EXPECT_EQ(source.find(weak), std::string::npos) << weak;
  // And it answers: 16 fresh bytes every time (two equal draws: 2^-128).
  unsigned char a[16] = {}, b[16] = {};
  os_random_bytes(a, sizeof a);
  os_random_bytes(b, sizeof b);
  EXPECT_NE(std::string(reinterpret_cast<char*>(a), 16), std::string(reinterpret_cast<char*>(b), 16));
  std::vector<unsigned char> big(1 << 20);
  os_random_bytes(big.data(), big.size());  // longer than one getrandom call may return
  // Served ids are 32 hex digits, all distinct.
  auto s = make();
  std::set<std::string> ids;
  for (int i = 0; i < 8; ++i) {
    const std::string id = id_of(create(*s, ""));
    EXPECT_EQ(id.size(), 32u);
    EXPECT_EQ(id.find_first_not_of("0123456789abcdef"), std::string::npos) << id;
    ids.insert(id);
  }
  EXPECT_EQ(ids.size(), 8u);
}

TEST_F(ServiceUnderHostileUse, OneClientCannotTakeEverySession) {
  ServiceLimits lim;
  lim.max_sessions = 6;
  lim.max_client_sessions = 2;
  auto s = make(lim);
  id_of(create(*s, "127.0.0.2"));
  id_of(create(*s, "127.0.0.2"));
  const Reply third = create(*s, "127.0.0.2");
  EXPECT_EQ(third.status, 429) << third.body;
  EXPECT_NE(body(third)["error"].get<std::string>().find("--max-client-sessions"), std::string::npos) << third.body;
  // Others are served; the owner is not counted.
  id_of(create(*s, "127.0.0.1"));
  id_of(create(*s, "127.0.0.2", /*owner=*/true));
  EXPECT_EQ(s->live_sessions(), 4u);
}

TEST_F(ServiceUnderHostileUse, AFullServerMakesRoomFromTheBiggestHolderOnceItIsIdle) {
  ServiceLimits lim;
  lim.max_sessions = 3;
  lim.max_client_sessions = 0;  // only the total: the filler may take all
  lim.evict_idle_seconds = 60;
  auto s = make(lim);
  const std::string f1 = id_of(create(*s, "filler")), f2 = id_of(create(*s, "filler"));
  clock.seconds += 10;
  const std::string honest = id_of(create(*s, "honest"));
  // Full, and nobody idle for 60 s yet: 503.
  EXPECT_EQ(create(*s, "newcomer").status, 503);
  clock.seconds += 55;  // filler's idle 65 s, honest 55 s
  const std::string newcomer = id_of(create(*s, "newcomer"));
  EXPECT_FALSE(newcomer.empty());
  // One of the filler's sessions made room; the honest one stays.
  EXPECT_EQ(s->handle("GET", "/api/sessions/" + honest, "").status, 200);
  const int filler_left = (s->handle("GET", "/api/sessions/" + f1, "").status == 200) +
                          (s->handle("GET", "/api/sessions/" + f2, "").status == 200);
  EXPECT_EQ(filler_left, 1);
  EXPECT_EQ(s->live_sessions(), 3u);
}

TEST_F(ServiceUnderHostileUse, MalformedJsonIsDescribedInOurWords) {
  auto s = make();
  const Reply r = s->handle("POST", "/api/sessions", R"j({"dataset": doors})j");
  ASSERT_EQ(r.status, 400);
  const std::string e = body(r)["error"];
  EXPECT_NE(e.find("malformed JSON body: not valid JSON at line 1, column 13"), std::string::npos) << e;
  EXPECT_NE(e.find("invalid literal"), std::string::npos) << e;
  EXPECT_EQ(e.find("json.exception"), std::string::npos) << e;
  EXPECT_EQ(e.find("parse_error"), std::string::npos) << e;
  const Reply big = s->handle("POST", "/api/sessions", R"j({"dataset": 1e999})j");
  ASSERT_EQ(big.status, 400);
  EXPECT_NE(body(big)["error"].get<std::string>().find("the number 1e999 is too large"), std::string::npos) << big.body;
}

TEST_F(ServiceUnderHostileUse, DomainAndProblemWithoutAPackPlayWithTheServersPack) {
  auto s = make();
  const json request = {{"domain", read(kExamples + "/domain.pddl")}, {"problem", read(kExamples + "/problems/e1.pddl")}};
  const Reply r = s->handle("POST", "/api/sessions", request.dump());
  ASSERT_EQ(r.status, 201) << r.body;
  EXPECT_EQ(body(r)["domain"], "doors-keys-gems");
}

// 45 objects and one three-object action: 91,125 actions applicable in the
// first state, more than the state graph's 65,535 (the probe's 500).
TEST_F(ServiceUnderHostileUse, AProblemTooLargeForThePlannersTablesIs4xx) {
  std::string objects;
  for (int i = 0; i < 45; ++i) objects += " o" + std::to_string(i);
  const std::string domain =
      "(define (domain wide) (:requirements :strips :typing) (:types agent thing)"
      " (:predicates (touched ?x - thing ?y - thing ?z - thing) (done))"
      " (:action touch :parameters (?a - agent ?x - thing ?y - thing ?z - thing) :effect (touched ?x ?y ?z))"
      " (:action finish :parameters (?a - agent ?x - thing) :precondition (touched ?x ?x ?x) :effect (done))"
      " (:action wait :parameters (?a - agent) :effect (and)))";
  const std::string problem = "(define (problem p) (:domain wide) (:objects human robot - agent" + objects +
                              " - thing) (:init) (:goal (done)))";
  const json pack = {{"domain", "wide"},
                     {"roles", {{"principal", "human"}, {"assistant", "robot"}, {"noop_action", "wait"}}},
                     {"goals", {{"source", "problem-goal"}}}};
  ServiceLimits lim;
  lim.max_pddl_bytes = 64 * 1024;
  auto s = make(lim);
  Reply r = s->handle("POST", "/api/sessions", json{{"domain", domain}, {"problem", problem}, {"pack", pack}}.dump());
  if (r.status == 201) {  // refused at the first step instead
    const std::string id = body(r)["id"];
    r = s->handle("POST", "/api/sessions/" + id + "/act", R"j({"action":"(touch human o1 o2 o3)"})j");
    s->handle("DELETE", "/api/sessions/" + id, "");
  }
  EXPECT_GE(r.status, 400) << r.body;
  EXPECT_LT(r.status, 500) << r.body;
  EXPECT_EQ(r.body.find("internal error"), std::string::npos) << r.body;
}

}  // namespace
}  // namespace clips::serve
