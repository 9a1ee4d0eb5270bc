// The public session API (include/clips/session.hpp): same posteriors as
// `clips infer`, errors that leave a session unchanged, assistance, threads.
#include <gtest/gtest.h>

#include <array>
#include <atomic>
#include <cmath>
#include <cstdio>
#include <thread>

#include <nlohmann/json.hpp>

#include "clips/clips.hpp"
#include "data/dataset.hpp"
#include "run_command.hpp"
#include "test_paths.hpp"

namespace {

std::string examples_dkg() { return clips::paths::examples_dir() + "/doors-keys-gems"; }

using clips::tests::stdout_of;

void expect_near_all(const std::vector<double>& a, const std::vector<double>& b, const std::string& where) {
  ASSERT_EQ(a.size(), b.size()) << where;
  for (size_t i = 0; i < a.size(); ++i) EXPECT_NEAR(a[i], b[i], 1e-9) << where << " goal " << i;
}

// Replays a dataset plan through a Session, an action and an utterance at a
// time, and compares every step with `clips infer --json` (utterances are
// heard in the state they were said in, the CLI's default timing).
void check_replay_matches_cli(const std::string& dataset, const std::string& plan_id) {
  const auto j = nlohmann::json::parse(stdout_of(std::string(CLIPS_BINARY_DIR) + "/clips infer --json --dataset " +
                                                 dataset + " --plan " + plan_id));
  const auto ds = clips::data::Dataset::load(dataset);
  const auto& plan = ds.plan(plan_id);
  const int T = static_cast<int>(plan.observed.actions.size());
  ASSERT_EQ(static_cast<int>(j["steps"].size()), T + 1);
  auto session = clips::Session::open_dataset(dataset, plan_id);
  EXPECT_EQ(session.posterior().goals, j["goals"].get<std::vector<std::string>>());
  for (int t = 0; t <= T; ++t) {
    if (t > 0) session.observe(plan.observed.actions[t - 1].text);
    auto hear_all = [&] {
      for (const auto& u : plan.observed.utterances)
        if (u.index == t) session.hear(u.text);
    };
    // The CLI's step t holds the utterances said after t actions only at the
    // start and the end; in between they are scored in step t + 1.
    if (t == 0 || t == T) hear_all();
    std::vector<double> expected;  // the engine's posterior JSON: goals [{goal, p}]
    for (const auto& g : j["steps"][t]["posterior"]["goals"]) expected.push_back(g["p"].get<double>());
    expect_near_all(session.posterior().goal_probabilities, expected, plan_id + " t=" + std::to_string(t));
    expect_near_all(session.trace().at(t).posterior.goal_probabilities, expected, plan_id + " trace t=" + std::to_string(t));
    if (t != 0 && t != T) hear_all();
  }
  EXPECT_EQ(session.t(), T);
}

TEST(Session, ReplayMatchesClipsInferOnTheRepoExamples) {
  check_replay_matches_cli(examples_dkg(), "e1.1.keys");
  check_replay_matches_cli(examples_dkg(), "e2.2.keys");
}

TEST(Session, ReplayMatchesClipsInferOnThePapersDataset) {
  if (!clips::paths::have_shared_dataset()) GTEST_SKIP() << "no shared dataset at " << clips::paths::dkg_dataset();
  check_replay_matches_cli(clips::paths::dkg_dataset(), "2.1.keys");
}

TEST(Session, InapplicableActionLeavesTheSessionUnchanged) {
  auto s = clips::Session::open_dataset(examples_dkg(), "e1.1.keys");
  s.observe("(left human)");
  const auto before = s.posterior();
  const std::string state = s.state();
  const size_t steps = s.trace().size();
  ASSERT_TRUE(s.assistant_turn());
  try {
    s.observe("(left human)");  // the robot is to move
    FAIL() << "expected InapplicableActionError";
  } catch (const clips::InapplicableActionError& e) {
    EXPECT_EQ(e.action(), "(left human)");
    EXPECT_NE(std::string(e.what()).find("(left human)"), std::string::npos) << e.what();
  }
  EXPECT_THROW(s.observe(-1), clips::InputError);
  EXPECT_EQ(s.state(), state);
  EXPECT_EQ(s.t(), 1);
  EXPECT_EQ(s.trace().size(), steps);
  EXPECT_EQ(s.posterior().goal_probabilities, before.goal_probabilities);
  EXPECT_EQ(s.posterior().log_marginal_likelihood, before.log_marginal_likelihood);
  // Still usable afterwards.
  s.observe("(wait robot)");
  EXPECT_EQ(s.t(), 2);
}

TEST(Session, UnknownActionsAndObjectsAreInputErrorsNamingThem) {
  auto s = clips::Session::open_dataset(examples_dkg(), "e1");
  for (const std::string bad : {"(fly human)", "(left nobody)", "left human", "(left human"}) {
    try {
      s.observe(bad);
      FAIL() << "expected an InputError for " << bad;
    } catch (const clips::InapplicableActionError& e) {
      FAIL() << bad << " is not well formed, yet was called inapplicable: " << e.what();
    } catch (const clips::InputError& e) {
      EXPECT_NE(std::string(e.what()).find(bad), std::string::npos) << e.what();
    }
  }
  EXPECT_THROW(s.hear(""), clips::InputError);
  EXPECT_THROW(s.hear("bad \xff byte"), clips::InputError);
  EXPECT_EQ(s.t(), 0);
  EXPECT_THROW(clips::Session::open_dataset(examples_dkg(), "nope"), clips::InputError);
  clips::SessionOptions o;
  o.language_model.backend = "gpt-nonsense";
  EXPECT_THROW(clips::Session::open_dataset(examples_dkg(), "e1", o), clips::InputError);
}

// issue 46: a 200 kB action text is an input error at once; every token's
// location used to copy the whole text (quadratic: 4 GB).
TEST(Session, AHugeActionTextIsAnInputErrorWithAShortLabel) {
  auto s = clips::Session::open_dataset(examples_dkg(), "e1");
  std::string huge = "(left";
  while (huge.size() < 200000) huge += " human";
  huge += ")";
  try {
    s.observe(huge);
    FAIL() << "a 200 kB action was accepted";
  } catch (const clips::InputError& e) {
    EXPECT_LT(std::string(e.what()).size(), 2000u);
    EXPECT_NE(std::string(e.what()).find("action (left human human"), std::string::npos)
        << std::string(e.what()).substr(0, 300);
  }
  EXPECT_EQ(s.t(), 0);
}

TEST(Session, AssistWeighsTheCandidatesWithTheGoalPosterior) {
  auto s = clips::Session::open_dataset(examples_dkg(), "e1.1.keys");
  for (const char* a : {"(left human)", "(wait robot)", "(left human)", "(wait robot)"}) s.observe(a);
  EXPECT_FALSE(s.assist().assistant_turn);  // the human is to move
  s.hear("Can you get me the yellow key?");
  s.observe("(left human)");
  const clips::AssistDecision d = s.assist();
  ASSERT_TRUE(d.assistant_turn);
  ASSERT_FALSE(d.candidates.empty());
  EXPECT_EQ(d.goal_weights, s.posterior().goal_probabilities);
  const clips::CandidateAction* chosen = nullptr;
  double best = -INFINITY;
  for (const auto& c : d.candidates) {
    EXPECT_NE(c.action.find("robot"), std::string::npos) << c.action;
    if (c.action == d.action) chosen = &c;
    best = std::max(best, c.value);
  }
  ASSERT_NE(chosen, nullptr) << d.action;
  if (!d.unanimous) {
    EXPECT_EQ(chosen->value, best);
  }
  // Asking does not change the belief, and the decision is applicable.
  const auto before = s.posterior();
  s.observe(d.action);
  EXPECT_EQ(s.trace().back().action, d.action);
  EXPECT_FALSE(s.trace().back().evidence);  // the robot's own action: an intervention
  // (Equal up to rounding: the step renormalises the same weights.)
  ASSERT_EQ(s.posterior().goal_probabilities.size(), before.goal_probabilities.size());
  for (size_t g = 0; g < before.goal_probabilities.size(); ++g)
    EXPECT_NEAR(s.posterior().goal_probabilities[g], before.goal_probabilities[g], 1e-12) << g;

  clips::SessionOptions pibar;
  pibar.assistance = clips::Assistance::PiBar;
  auto p = clips::Session::open_dataset(examples_dkg(), "e1.1.keys", pibar);
  p.observe("(left human)");
  const auto dp = p.assist();
  double total = 0;
  for (const auto& c : dp.candidates) total += c.value;
  EXPECT_NEAR(total, 1.0, 1e-12);  // pi-bar values are the mixture's probabilities
}

// The rule that ends a deadlock holds in a session too: on the workshop
// (request rule) the robot waits for the human walking to the rack, but after
// a round in which both of them waited it does not wait again.
TEST(Session, TheAssistantDoesNotAnswerARoundOfWaitsWithAnotherWait) {
  auto s = clips::Session::open_dataset(clips::paths::source_dir() + "/data/datasets/workshop", "1");
  s.observe("(move human bench rack)");
  EXPECT_EQ(s.assist().action, "(wait robot)");
  s.observe("(wait robot)");
  s.observe("(wait human)");
  const clips::AssistDecision d = s.assist();
  ASSERT_TRUE(d.assistant_turn);
  EXPECT_NE(d.action, "(wait robot)");
}

TEST(Session, CallLimitsUndoResetAndGoalsThroughThePublicApi) {
  // issue 44: a robot's controller bounds and cancels calls; a stopped call
  // leaves the session as it was.
  auto s = clips::Session::open_dataset(examples_dkg(), "e1");
  s.observe("(left human)");
  const auto before = s.posterior();
  clips::CallLimits none_left;
  none_left.seconds = 0;
  EXPECT_THROW(s.observe("(wait robot)", none_left), clips::TimeLimitError);
  std::atomic<bool> stop{true};
  clips::CallLimits cancelled;
  cancelled.cancel = &stop;
  EXPECT_THROW(s.hear("Can you get me the yellow key?", cancelled), clips::CancelledError);
  EXPECT_EQ(s.t(), 1);
  EXPECT_EQ(s.trace().size(), 2u);
  EXPECT_EQ(s.posterior().goal_probabilities, before.goal_probabilities);
  EXPECT_EQ(s.posterior().log_marginal_likelihood, before.log_marginal_likelihood);
  s.observe("(wait robot)");
  EXPECT_TRUE(s.undo());  // the human's move and the robot's wait after it
  EXPECT_EQ(s.t(), 0);
  EXPECT_FALSE(s.undo());
  s.observe("(left human)");
  s.reset();
  EXPECT_EQ(s.t(), 0);
  EXPECT_EQ(s.trace().size(), 1u);
  EXPECT_FALSE(s.goal_holds("gem1"));
  EXPECT_THROW(s.goal_holds("gem9"), clips::InputError);
}

TEST(Session, MethodsReadTheirOwnEvidence) {
  clips::SessionOptions lang;
  lang.method = clips::Method::LanguageOnly;
  auto s = clips::Session::open_dataset(examples_dkg(), "e1.1.keys", lang);
  for (const char* a : {"(left human)", "(wait robot)", "(left human)"}) s.observe(a);
  // No utterance yet: language-only is still the uniform prior, action-only is not.
  for (double p : s.posterior().goal_probabilities) EXPECT_NEAR(p, 0.25, 1e-12);
  EXPECT_NE(s.posterior(clips::Method::ActionOnly).goal_probabilities, s.posterior().goal_probabilities);
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

TEST(Session, OpensADomainFolderAndProblemFile) {
  auto s = clips::Session::open_domain(examples_dkg(), examples_dkg() + "/problems/e1.pddl");
  EXPECT_EQ(s.domain(), "doors-keys-gems");
  EXPECT_EQ(s.posterior().goals.size(), 4u);
  EXPECT_EQ(s.posterior().cost_profiles, (std::vector<std::string>{"C3", "C4"}));
  EXPECT_NE(s.state().find('h'), std::string::npos);
  EXPECT_THROW(clips::Session::open_domain(examples_dkg(), "/nonexistent.pddl"), clips::InputError);
  EXPECT_EQ(clips::library_version(), std::string(clips::kVersion));
}

}  // namespace
