#include "serve/pack_sessions_test.hpp"

namespace clips::serve {
namespace pack_sessions_test {
// A pack whose no-op is `idle` and whose turn predicate is `turn` (neither
// in its domain: clips compiles them) plays over the JSON API: the bot
// answers the gardener's moves with the pack's actions.
TEST(PackSessionsIdle, AnIdleAndTurnPackPlays) {
  Service s({std::string(CLIPS_SOURCE_DIR) + "/tests/fixtures/garden"}, {}, shared_lm());
  Reply r = s.handle("POST", "/api/sessions", R"j({"dataset":"garden","problem":"1"})j");
  ASSERT_EQ(r.status, 201) << r.body;
  json st = body(r);
  EXPECT_EQ(st["turn"], "gardener");
  const std::string url = "/api/sessions/" + st["id"].get<std::string>();
  r = s.handle("POST", url + "/act", R"j({"action":"(idle gardener)"})j");
  ASSERT_EQ(r.status, 200) << r.body;
  EXPECT_EQ(body(r)["turn"], "bot");
  r = s.handle("POST", url + "/hear", R"j({"utterance":"Could you get the green seeds?"})j");
  ASSERT_EQ(r.status, 200) << r.body;
  r = s.handle("POST", url + "/assist", R"j({"apply":true})j");
  ASSERT_EQ(r.status, 200) << r.body;
  const json reply = body(r);
  EXPECT_EQ(reply["state"]["turn"], "gardener") << r.body;
  const std::string action = reply["decision"]["action"];
  EXPECT_EQ(action.rfind("(", 0), 0u) << r.body;
  EXPECT_NE(action.find(" bot"), std::string::npos) << r.body;  // the bot's own action: (idle bot), (move bot ...), ...
}

}  // namespace pack_sessions_test

}  // namespace clips::serve
