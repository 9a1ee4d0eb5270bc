#include "inference/dataset_test.hpp"

namespace clips::inference {
namespace dataset_test {
TEST(AssistantTurns, TakenLeavesTheExamplePosteriorsUnchanged) {
  expect_assistant_turns_do_not_move_posteriors(paths::examples_dir() + "/doors-keys-gems", 4);
}

// An utterance at the assistant's turn (observe) or after the last action
// (hear) is explained by each hypothesis' rollout from the state. A
// hypothesis with a stored plan from there follows it whatever is refined, so
// the default refines it no further than a silent turn would; the
// utterance's scores, and every posterior, must equal the spec's REFINE.
TEST(AssistantTurns, UtterancesAtTheAssistantsTurnsReuseTheStoredPlans) {
  auto lm = embedded_lm();
  if (!lm) GTEST_SKIP() << "no embedded LM";
  auto ds = data::Dataset::load(paths::examples_dir() + "/doors-keys-gems");
  const data::PlanRecord& plan = ds.plan("e2.2.keys");
  auto task = ds.task(plan.problem_id);
  const pddl::Simulation sim = pddl::simulate(*task, task->initial_state(), plan.observed);
  ASSERT_EQ(sim.actions.size(), 6u);
  InferenceOptions all_opts;
  all_opts.assistant_turns = AssistantTurns::All;
  Belief taken(task, ds.pack_ptr(), ds.candidate_goals(plan), plan_cost_profiles(ds.pack(), plan).profiles);
  Belief all(task, ds.pack_ptr(), ds.candidate_goals(plan), plan_cost_profiles(ds.pack(), plan).profiles, all_opts);
  const size_t n = taken.hypotheses().size();
  auto expect_same_scores = [&](const StepRecord& a, const StepRecord& b, const std::string& where) {
    ASSERT_EQ(a.utterances.size(), b.utterances.size()) << where;
    for (size_t u = 0; u < a.utterances.size(); ++u)
      for (size_t h = 0; h < n; ++h) {
        const auto& x = a.utterances[u].hypotheses[h];
        const auto& y = b.utterances[u].hypotheses[h];
        EXPECT_EQ(x.log_likelihood, y.log_likelihood) << where << " hypothesis " << h;
        ASSERT_EQ(x.commands.size(), y.commands.size()) << where << " hypothesis " << h;
        for (size_t c = 0; c < x.commands.size(); ++c) EXPECT_EQ(x.commands[c].command, y.commands[c].command);
      }
    for (Modality m : kModalities)
      for (size_t h = 0; h < n; ++h) EXPECT_NEAR(a[m].hypotheses[h], b[m].hypotheses[h], 1e-9) << where;
  };
  taken.start(sim.states[0]);
  all.start(sim.states[0]);
  StepRecord last_taken, last_all;
  for (size_t t = 0; t < sim.actions.size(); ++t) {
    // The fourth action is the assistant's wait; an instruction comes with it.
    std::vector<std::string> said;
    if (t == 3) said = {"Can you get the red key for me?"};
    size_t stored = 0;
    for (size_t h = 0; h < n; ++h) stored += taken.policies()[h].on_stored_path(sim.states[t]) ? 1 : 0;
    const size_t before = taken.refinements();
    last_taken = taken.observe(sim.actions[t], sim.states[t], said, lm.get());
    last_all = all.observe(sim.actions[t], sim.states[t], said, lm.get());
    EXPECT_EQ(last_taken.evidence, t % 2 == 0);  // the human moves first
    expect_same_scores(last_taken, last_all, "step " + std::to_string(t + 1));
    if (t == 3) {
      ASSERT_EQ(last_taken.utterances.size(), 1u);
      // Once each: toward the wait, or in full without a stored plan.
      EXPECT_EQ(taken.refinements() - before, n);
      EXPECT_GT(stored, 0u);  // some plans were reused
    }
  }
  // After the last action a hypothesis on a stored plan is not refined.
  const pddl::State& end = sim.states.back();
  std::vector<size_t> values(n);
  std::vector<bool> on_plan(n);
  size_t stored = 0;
  for (size_t h = 0; h < n; ++h) {
    values[h] = taken.policies()[h].table_size();
    on_plan[h] = taken.policies()[h].on_stored_path(end);
    stored += on_plan[h] ? 1 : 0;
  }
  EXPECT_GT(stored, 0u);
  const size_t before_taken = taken.refinements(), before_all = all.refinements();
  const std::vector<std::string> said = {plan.observed.utterances.back().text};
  expect_same_scores(taken.hear(said, *lm, last_taken), all.hear(said, *lm, last_all), "hear");
  EXPECT_EQ(all.refinements() - before_all, n);
  EXPECT_EQ(taken.refinements() - before_taken, n - stored);
  for (size_t h = 0; h < n; ++h)
    if (on_plan[h]) {
      EXPECT_EQ(taken.policies()[h].table_size(), values[h]) << "hypothesis " << h;
    }
}

}  // namespace dataset_test

}  // namespace clips::inference
