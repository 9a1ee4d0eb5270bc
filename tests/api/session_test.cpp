#include "api/session_test.hpp"

namespace session_test {
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

TEST(Session, OpensADomainFolderAndProblemFile) {
  auto s = clips::Session::open_domain(examples_dkg(), examples_dkg() + "/problems/e1.pddl");
  EXPECT_EQ(s.domain(), "doors-keys-gems");
  EXPECT_EQ(s.posterior().goals.size(), 4u);
  EXPECT_EQ(s.posterior().cost_profiles, (std::vector<std::string>{"C3", "C4"}));
  EXPECT_NE(s.state().find('h'), std::string::npos);
  EXPECT_THROW(clips::Session::open_domain(examples_dkg(), "/nonexistent.pddl"), clips::InputError);
  EXPECT_EQ(clips::library_version(), std::string(clips::kVersion));
}

}  // namespace session_test
