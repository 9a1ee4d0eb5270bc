#include "api/session_test.hpp"

namespace session_test {
TEST(Session, ReplayMatchesClipsInferOnTheRepoExamples) {
  check_replay_matches_cli(examples_dkg(), "e1.1.keys");
  check_replay_matches_cli(examples_dkg(), "e2.2.keys");
}

// Distinct sessions on distinct threads (run under TSan by the sanitizer job).
TEST(Session, TwoSessionsOnTwoThreadsAgreeWithOneThread) {
  auto replay = [](const std::string& plan, const std::vector<std::string>& actions, const std::string& said) {
    auto s = clips::Session::open_dataset(examples_dkg(), plan);
    for (const auto& a : actions) s.observe(a);
    s.hear(said);
    return s.posterior().goal_probabilities;
  };
  const std::vector<std::string> a1 = {"(left human)", "(wait robot)"}, a2 = {"(up human)", "(wait robot)"};
  std::vector<double> r1, r2;
  std::thread t1([&] { r1 = replay("e1.1.keys", a1, "Can you get me the yellow key?"); });
  std::thread t2([&] { r2 = replay("e2.1.doors", a2, "Can you unlock the yellow door for me?"); });
  t1.join();
  t2.join();
  EXPECT_EQ(r1, replay("e1.1.keys", a1, "Can you get me the yellow key?"));
  EXPECT_EQ(r2, replay("e2.1.doors", a2, "Can you unlock the yellow door for me?"));
}

// tests/fixtures/garden: a pack whose no-op is `idle` and whose turn
// predicate is `turn`, on a domain that writes neither (clips compiles the
// turns in, the gardener first). The session keeps the turns and assists.
TEST(Session, AssistsWithThePacksNoOpAndTurnPredicate) {
  const std::string garden = clips::paths::source_dir() + "/tests/fixtures/garden";
  auto s = clips::Session::open_domain(garden, garden + "/problems/1.pddl");
  EXPECT_EQ(s.posterior().goals, (std::vector<std::string>{"tomato1", "basil1"}));
  EXPECT_EQ(s.active_agent(), "gardener");
  EXPECT_FALSE(s.assist().assistant_turn);
  EXPECT_THROW(s.observe("(take bot basil1 shed)"), clips::InapplicableActionError);  // not the bot's turn
  s.observe("(idle gardener)");
  EXPECT_EQ(s.active_agent(), "bot");
  s.hear("Could you bring me the green seeds?");
  const auto post = s.posterior();
  EXPECT_GT(post.goal_probabilities[1], post.goal_probabilities[0]);
  const auto d = s.assist();
  ASSERT_TRUE(d.assistant_turn);
  EXPECT_EQ(d.action, "(take bot basil1 shed)");
  for (const auto& c : d.candidates) EXPECT_NE(c.action.find(" bot"), std::string::npos) << c.action;
  s.observe(d.action);
  EXPECT_EQ(s.active_agent(), "gardener");
  // The same folder as a dataset plan.
  auto ds = clips::Session::open_dataset(garden, "1.1.basil");
  ds.observe("(idle gardener)");
  EXPECT_TRUE(ds.assist().assistant_turn);
}

}  // namespace session_test
