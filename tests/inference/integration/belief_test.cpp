#include "inference/belief_test.hpp"

namespace clips::inference {
namespace belief_test {
// The lab's 5.2: the principal fetches the culture and the enzyme of a
// digestion from the fridge the robot stands at, which the best joint plan
// would have left to the robot. Read as a cooperative planner that is evidence
// against the digestion; the alone twin of the default profile explains it.
TEST(AloneTwins, FetchingWhatTheAssistantCouldHaveFetchedPointsToTheGoal) {
  auto lm = language::make_language_model("embedded");
  const auto ds = data::Dataset::load(paths::source_dir() + "/data/datasets/lab");
  const InferenceRun run = run_inference(ds, ds.plan("5.2.digestion"), *lm);
  ASSERT_EQ(run.profiles, (std::vector<std::string>{"default", "default-alone"}));
  EXPECT_EQ(run.true_profile, 0);
  const Posterior& actions = run.final_posterior(Modality::ActionOnly);
  EXPECT_EQ(std::max_element(actions.goals.begin(), actions.goals.end()) - actions.goals.begin(), run.true_goal);
  EXPECT_GT(actions.goals[static_cast<size_t>(run.true_goal)], 0.5);
  double base = 0, twin = 0;
  for (size_t h = 0; h < run.belief->hypotheses().size(); ++h) {
    const Hypothesis& hyp = run.belief->hypotheses()[h];
    if (hyp.goal != run.true_goal) continue;
    (hyp.profile == 0 ? base : twin) += actions.hypotheses[h];
  }
  EXPECT_GT(twin, 10 * base);
}

// A twin models how the principal acts, not what they would say: its words
// are scored against its base's joint plans, so "can you get the rest?" is
// a request for the same help under both.
TEST(AloneTwins, ATwinSpeaksAsItsBase) {
  auto lm = language::make_language_model("embedded");
  const auto ds = data::Dataset::load(paths::source_dir() + "/data/datasets/lab");
  const InferenceRun run = run_inference(ds, ds.plan("5.2.digestion"), *lm);
  const UtteranceRecord* said = last_utterance(run);
  ASSERT_NE(said, nullptr);
  const auto& hyps = run.belief->hypotheses();
  const size_t profiles = run.profiles.size();
  ASSERT_EQ(said->hypotheses.size(), hyps.size());
  for (size_t h = 0; h < hyps.size(); ++h) {
    if (hyps[h].profile == 0) continue;
    const size_t b = static_cast<size_t>(hyps[h].goal) * profiles;
    ASSERT_EQ(hyps[b].profile, 0);
    EXPECT_EQ(run.belief->base_of(h), static_cast<int>(b));
    EXPECT_DOUBLE_EQ(said->hypotheses[h].log_likelihood, said->hypotheses[b].log_likelihood);
    ASSERT_EQ(said->hypotheses[h].commands.size(), said->hypotheses[b].commands.size());
    for (size_t c = 0; c < said->hypotheses[h].commands.size(); ++c)
      EXPECT_EQ(said->hypotheses[h].commands[c].command, said->hypotheses[b].commands[c].command);
  }
  // The words ask the robot for the pipette under the digestion's joint plans.
  const size_t d = static_cast<size_t>(run.true_goal) * profiles;
  const auto& cs = said->hypotheses[d].commands;
  ASSERT_FALSE(cs.empty());
  const auto top = std::max_element(cs.begin(), cs.end(), [](auto& a, auto& b) { return a.posterior < b.posterior; });
  EXPECT_NE(top->command.find("pipette"), std::string::npos) << top->command;
}

// The garden's 4.1: the cheapest joint plan for feeding the roses has the
// principal walk to the greenhouse for the hose while the robot waits, so a
// cooperative speaker has nothing to ask; yet they ask the robot to "go in
// there and get me the big one". The delegating speakers (the robot does all
// it usefully can) hold that request, and the words then point to the goal.
TEST(DelegatingSpeaker, ARequestForWhatTheCheapestPlanLeavesToThePrincipal) {
  const DatasetPlanRun r("garden", "4.1.feed-roses");
  ASSERT_GT(r.ds.pack().spec().inference.speaker_delegates, 0);
  bool asks_for_hose = false;
  for (const CommandScore& c : r.true_goal_commands())
    asks_for_hose = asks_for_hose || (c.command.rfind("(pickup you ?hose1", 0) == 0 && c.posterior > 0.5);
  EXPECT_TRUE(asks_for_hose);
  EXPECT_GT(r.run.p_true_goal(Modality::Both), 0.5);
  EXPECT_GT(r.run.p_true_goal(Modality::Both), r.run.p_true_goal(Modality::ActionOnly));
}

// The kitchen's 1.3: "I'll grab a bowl. Can you get an egg out of the
// fridge?" after the flour. Only the cake takes the bowl; by default the
// speaker model keeps the speaker's own part of a joint command, so the
// first clause is read as the plan it states, not as noise.
TEST(JointStatement, TheSpeakersOwnPartIsReadAsThePlan) {
  const DatasetPlanRun r("kitchen", "1.3.cake");
  double own_bowl = 0;
  for (const CommandScore& c : r.true_goal_commands())
    if (c.command.find("(pickup me ?bowl1") != std::string::npos) own_bowl += c.posterior;
  EXPECT_GT(own_bowl, 0.5);
  EXPECT_GT(r.run.p_true_goal(Modality::Both), 0.9);
  EXPECT_GT(r.run.p_true_goal(Modality::Both), r.run.p_true_goal(Modality::ActionOnly));
}

// The kitchen's 1.1: "Can you open the cupboard for me, and then fetch the
// flour?" In the cheapest joint plan the cook opens the cupboard, so the
// speaker model favours "I open the cupboard, you fetch the flour" ten to
// one; a clause that opens with "can you" is a request all the same
// (EncodedUtterance::subject), so the words must carry the listener's
// opening (0.10 of the true goal's commands before, 0.62 now).
TEST(AddressedClause, CanYouOpenIsTheListenersOpening) {
  const DatasetPlanRun r("kitchen", "1.1.pancakes");
  double yours = 0, mine = 0;
  for (const CommandScore& c : r.true_goal_commands()) {
    if (c.command.find("(open you cupboard1)") != std::string::npos) yours += c.posterior;
    if (c.command.find("(open me cupboard1)") != std::string::npos) mine += c.posterior;
  }
  EXPECT_GT(yours, 0.5);
  EXPECT_GT(yours, mine);
}

// The lab's 6.4: "Right, distillation next. Could you dig the instrument
// out of the drawer for me?" after the solvent. Calibration and distillation
// both take the solvent and the thermometer, so the request alone cannot
// tell them apart; the goal's name does, and the speaker may state the goal
// and ask in one breath (language.goal_with_command): 0.49 before, 0.80 now.
TEST(GoalWithCommand, DistillationNextThenARequest) {
  const DatasetPlanRun r("lab", "6.4.distillation");
  EXPECT_GT(r.run.p_true_goal(Modality::Both), 0.7);
  EXPECT_GT(r.run.p_true_goal(Modality::Both), r.run.p_true_goal(Modality::ActionOnly) + 0.2);
}

// The kitchen's 5.3: "Hmm, I'll need something sharp for this." after the
// banana. The fruit salad takes the big metal knife, the smoothie a spoon:
// read through WordNet, "sharp" is what a knife is, so the words point to
// the salad (before, the smoothie kept 0.70).
TEST(FunctionWords, SomethingSharpIsAKnife) {
  const DatasetPlanRun r("kitchen", "5.3.fruitsalad");
  EXPECT_GT(r.run.p_true_goal(Modality::Both), 0.8);
  EXPECT_GT(r.run.p_true_goal(Modality::Both), r.run.p_true_goal(Modality::ActionOnly) + 0.3);
}

}  // namespace belief_test

}  // namespace clips::inference
