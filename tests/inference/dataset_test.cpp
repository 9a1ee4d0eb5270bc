// Inference on the paper's datasets (skipped when ../shared/dataset is absent).
#include <gtest/gtest.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <memory>

#include "inference/belief.hpp"
#include "pddl/plan.hpp"
#include "domains/vh_value.hpp"
#include "language/listener.hpp"
#include "test_paths.hpp"

namespace clips::inference {
namespace {

std::shared_ptr<lm::LanguageModel> embedded_lm() {
  try {
    return language::make_language_model("embedded");
  } catch (const std::exception& e) {
    std::printf("embedded LM unavailable: %s\n", e.what());
    return nullptr;
  }
}

void expect_sane(const Posterior& p) {
  double sum = 0;
  for (double x : p.goals) {
    EXPECT_GE(x, 0.0);
    EXPECT_LE(x, 1.0);
    sum += x;
  }
  EXPECT_NEAR(sum, 1.0, 1e-9);
}

TEST(DkgDataset, UtteranceRaisesTrueGoalOn2_1Keys) {
  if (!paths::have_shared_dataset()) GTEST_SKIP() << "no dataset";
  auto lm = embedded_lm();
  if (!lm) GTEST_SKIP() << "no embedded LM";
  auto ds = data::Dataset::load(paths::dkg_dataset());
  const auto& plan = ds.plan("2.1.keys");
  const InferenceRun run = run_inference(ds, plan, *lm);
  ASSERT_EQ(run.goals[run.true_goal], "gem2");
  ASSERT_EQ(run.steps.size(), 11u);
  EXPECT_EQ(run.belief->hypotheses().size(), 8u);
  const double both = run.p_true_goal(Modality::Both), action = run.p_true_goal(Modality::ActionOnly),
               utterance = run.p_true_goal(Modality::UtteranceOnly);
  std::printf("2.1.keys P(gem2): both %.4f  action-only %.4f  utterance-only %.4f  (%.2f s)\n", both, action,
              utterance, run.seconds);
  EXPECT_GT(both, action);
  // The utterance is attached to the last step (index 10 = T), scored at s_9.
  ASSERT_EQ(run.steps.back().utterances.size(), 1u);
  for (const auto& h : run.steps.back().utterances[0].hypotheses) {
    double z = 0;
    for (const auto& c : h.commands) z += c.posterior;
    if (!h.commands.empty()) {
      EXPECT_NEAR(z, 1.0, 1e-9);
    }
  }
}

TEST(DkgDataset, AllPlansThreeModalities) {
  if (!paths::have_shared_dataset()) GTEST_SKIP() << "no dataset";
  // With h_max instead of the MST heuristic the 2^18-node refinements take
  // ~18 min for all plans (more than ctest's 900 s limit): opt in explicitly.
  if (domains::builtin_pack("doors-keys-gems")->spec().inference.heuristic != "dkg-mst" && !std::getenv("CLIPS_INFER_ALL_PLANS"))
    GTEST_SKIP() << "dkg-mst not registered yet; set CLIPS_INFER_ALL_PLANS=1 to run with h_max";
  auto lm = embedded_lm();
  if (!lm) GTEST_SKIP() << "no embedded LM";
  auto ds = data::Dataset::load(paths::dkg_dataset());
  std::printf("%-14s %8s %8s %8s %6s %8s\n", "plan", "both", "action", "utter", "steps", "seconds");
  double total = 0, sum[3] = {0, 0, 0}, min_both = 1;
  int n = 0, both_at_least_action = 0;
  std::vector<double> step_times;
  for (const auto& plan : ds.plans()) {
    const InferenceRun run = run_inference(ds, plan, *lm);
    for (const auto& st : run.steps) {
      for (Modality m : kModalities) expect_sane(st[m]);
      step_times.push_back(st.seconds);
    }
    const double p[3] = {run.p_true_goal(Modality::Both), run.p_true_goal(Modality::ActionOnly),
                         run.p_true_goal(Modality::UtteranceOnly)};
    std::printf("%-14s %8.4f %8.4f %8.4f %6zu %8.2f\n", plan.id.c_str(), p[0], p[1], p[2], run.steps.size(),
                run.seconds);
    std::fflush(stdout);
    if (plan.evaluated) {
      for (int i = 0; i < 3; ++i) sum[i] += p[i];
      ++n;
      if (p[0] >= p[1] - 1e-9) ++both_at_least_action;
      min_both = std::min(min_both, p[0]);
    }
    total += run.seconds;
  }
  std::sort(step_times.begin(), step_times.end());
  std::printf("mean over %d evaluated plans: both %.4f  action %.4f  utterance %.4f; total %.1f s, median step %.4f s\n",
              n, sum[0] / n, sum[1] / n, sum[2] / n, total, step_times[step_times.size() / 2]);
  // What the README and the paper claim (Table 1, P(g_true) of the three
  // inverse planners: 0.74 / 0.55 / 0.31 in the paper, 0.79 / 0.56 / 0.33
  // here), with margins: CLIPS ahead of language alone ahead of actions alone.
  ASSERT_EQ(n, 24);
  const double both = sum[0] / n, action = sum[1] / n, utterance = sum[2] / n;
  EXPECT_GE(both, 0.70);
  EXPECT_GE(utterance, 0.45);
  EXPECT_LE(utterance, 0.70);
  EXPECT_GE(action, 0.22);
  EXPECT_LE(action, 0.45);
  EXPECT_GT(both, utterance + 0.1);
  EXPECT_GT(utterance, action + 0.1);
  // Per plan: language on top of the actions helps (measured on all 24 plans;
  // two may slip) and never leaves the true goal unlikely.
  EXPECT_GE(both_at_least_action, n - 2);
  EXPECT_GE(min_both, 0.4);
}

// VH spec Appendix A.2: h_g at s_0 of problem 2, without and with (nograb actor).
TEST(VhDataset, HeuristicTestVectors) {
  if (!std::filesystem::exists(paths::vh_dataset() + "/domain.pddl")) GTEST_SKIP() << "no VH dataset";
  auto ds = data::Dataset::load(paths::vh_dataset());
  auto task = ds.task("2");
  domains::VhValueHeuristic h(*task);
  pddl::State s0 = task->initial_state();
  pddl::State nograb = s0;
  task->set(nograb, task->atom("nograb", {"actor"}), true);
  struct Row { const char* goal; double h, h_nograb; };
  for (const Row& r : {Row{"plate1", 4, 5}, Row{"set_table2", 15, 21}, Row{"set_table4b", 36, 52}}) {
    model::Specification spec(task, ds.goal_definitions().at(r.goal), model::unit_profile());
    h.prepare(spec, s0);
    EXPECT_EQ(h.estimate(s0), r.h) << r.goal;
    EXPECT_EQ(h.estimate(nograb), r.h_nograb) << r.goal;
  }
}

// VH spec 6.7: commands of plan 2.1 at s_2 (the utterance's scoring state).
TEST(VhDataset, CommandSetsOfPlan2_1) {
  if (!std::filesystem::exists(paths::vh_dataset() + "/domain.pddl")) GTEST_SKIP() << "no VH dataset";
  auto ds = data::Dataset::load(paths::vh_dataset());
  const auto& plan = ds.plan("2.1.set_table1");
  auto task = ds.task(plan.problem_id);
  auto goals = ds.candidate_goals(plan);
  Belief b(task, ds.pack_ptr(), goals, {model::unit_profile()});
  EXPECT_FALSE(b.searches());
  const auto sim = pddl::simulate(*task, task->initial_state(), plan.observed);
  const pddl::State& s2 = sim.states[2];
  auto count = [&](const std::string& label) {
    for (size_t h = 0; h < b.hypotheses().size(); ++h)
      if (goals[b.hypotheses()[h].goal].label == label)
        return b.utterance_model().commands_at(b.policies()[h], s2).size();
    return size_t{0};
  };
  EXPECT_EQ(count("set_table1"), 6u);
  EXPECT_EQ(count("plate1"), 1u);
  EXPECT_EQ(count("set_table1b"), 10u);
  EXPECT_EQ(count("plate3"), 3u);
}

TEST(VhDataset, InferenceOnPlan2_1) {
  if (!std::filesystem::exists(paths::vh_dataset() + "/domain.pddl")) GTEST_SKIP() << "no VH dataset";
  auto lm = embedded_lm();
  if (!lm) GTEST_SKIP() << "no embedded LM";
  auto ds = data::Dataset::load(paths::vh_dataset());
  const InferenceRun run = run_inference(ds, ds.plan("2.1.set_table1"), *lm);
  for (const auto& st : run.steps)
    for (Modality m : kModalities) expect_sane(st[m]);
  std::printf("VH 2.1.set_table1 P(g_true): both %.4f action %.4f utterance %.4f (%.3f s)\n",
              run.p_true_goal(Modality::Both), run.p_true_goal(Modality::ActionOnly),
              run.p_true_goal(Modality::UtteranceOnly), run.seconds);
  // Actions alone leave the table-setting goals confused (0.08); the
  // instruction lifts the true goal (0.48 with the embedded model), and the
  // two together beat each alone.
  const double both = run.p_true_goal(Modality::Both), action = run.p_true_goal(Modality::ActionOnly),
               utterance = run.p_true_goal(Modality::UtteranceOnly);
  EXPECT_LE(action, 0.2);
  EXPECT_GE(both, 0.35);
  EXPECT_GT(both, action + 0.2);
  EXPECT_GT(both, utterance);
}

// At the assistant's turns nothing is scored, so one lookahead from the state
// the assistant's action led to (the default) must give the spec's posteriors
// (a lookahead from every successor) on every plan, with less search.
void expect_assistant_turns_do_not_move_posteriors(const std::string& dir, int min_plans) {
  auto lm = embedded_lm();
  if (!lm) GTEST_SKIP() << "no embedded LM";
  auto ds = data::Dataset::load(dir);
  int compared = 0;
  size_t taken_values = 0, all_values = 0;
  for (const auto& plan : ds.plans()) {
    InferenceOptions taken, all;
    all.assistant_turns = AssistantTurns::All;
    const InferenceRun a = run_inference(ds, plan, *lm, all);
    const InferenceRun b = run_inference(ds, plan, *lm, taken);
    ASSERT_EQ(a.searches_stopped_by_budget, 0u) << plan.id;
    ASSERT_EQ(a.steps.size(), b.steps.size());
    for (size_t t = 0; t < a.steps.size(); ++t)
      for (Modality m : kModalities)
        for (size_t h = 0; h < a.steps[t][m].hypotheses.size(); ++h)
          EXPECT_NEAR(a.steps[t][m].hypotheses[h], b.steps[t][m].hypotheses[h], 1e-9) << plan.id << " step " << t;
    for (size_t h = 0; h < a.policies().size(); ++h) {
      all_values += a.policies()[h].table_size();
      taken_values += b.policies()[h].table_size();
    }
    ++compared;
  }
  EXPECT_GE(compared, min_plans);
  EXPECT_LT(taken_values, all_values);  // it learned less: it searched less
}

TEST(AssistantTurns, TakenLeavesTheExamplePosteriorsUnchanged) {
  expect_assistant_turns_do_not_move_posteriors(paths::examples_dir() + "/doors-keys-gems", 4);
}

TEST(AssistantTurns, TakenLeavesThePaperPosteriorsUnchanged) {
  if (!paths::have_shared_dataset()) GTEST_SKIP() << "no dataset";
  expect_assistant_turns_do_not_move_posteriors(paths::dkg_dataset(), 27);
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

TEST(ParallelRefinement, SameBeliefOnAnyNumberOfThreads) {
  // The project's own examples (always present): every step's posterior and
  // every policy's tables must not depend on how many threads refine them.
  auto lm = embedded_lm();
  if (!lm) GTEST_SKIP() << "no embedded LM";
  auto ds = data::Dataset::load(paths::examples_dir() + "/doors-keys-gems");
  int compared = 0;
  for (const auto& plan : ds.plans()) {
    InferenceOptions one, two;
    two.threads = 2;
    const InferenceRun a = run_inference(ds, plan, *lm, one);
    const InferenceRun b = run_inference(ds, plan, *lm, two);
    ASSERT_EQ(a.steps.size(), b.steps.size());
    for (size_t t = 0; t < a.steps.size(); ++t)
      for (Modality m : kModalities) EXPECT_EQ(a.steps[t][m].hypotheses, b.steps[t][m].hypotheses) << plan.id;
    for (size_t h = 0; h < a.policies().size(); ++h) {
      EXPECT_EQ(a.policies()[h].table_size(), b.policies()[h].table_size());
      EXPECT_EQ(a.policies()[h].tree_size(), b.policies()[h].tree_size());
      EXPECT_EQ(a.policies()[h].value(a.belief->state()), b.policies()[h].value(b.belief->state()));
    }
    ++compared;
  }
  EXPECT_GE(compared, 4);
}

TEST(VhDataset, UtteranceExplainedFromTheStateItWasSaidIn) {
  // 2.8.plate2: the actor takes a plate, then says "Grab another plate."
  // Explained from s_k (after the grab) the two-plate goal wins; explained
  // from s_{k-1} (the reference code's alignment), where the actor holds no
  // plate yet, the one-plate goal does.
  if (!paths::have_shared_dataset()) GTEST_SKIP() << "no dataset";
  auto lm = embedded_lm();
  if (!lm) GTEST_SKIP() << "no embedded LM";
  auto ds = data::Dataset::load(paths::vh_dataset());
  const auto& plan = ds.plan("2.8.plate2");
  InferenceOptions after, before;
  before.utterance_timing = UtteranceTiming::Before;
  const InferenceRun a = run_inference(ds, plan, *lm, after);
  const InferenceRun b = run_inference(ds, plan, *lm, before);
  auto index_of = [&](const std::string& g) {
    return static_cast<size_t>(std::find(a.goals.begin(), a.goals.end(), g) - a.goals.begin());
  };
  const size_t one = index_of("plate1"), two = index_of("plate2");
  ASSERT_LT(two, a.goals.size());
  const auto& pa = a.final_posterior(Modality::Both).goals;
  const auto& pb = b.final_posterior(Modality::Both).goals;
  EXPECT_GT(pa[two], pa[one]);
  EXPECT_GT(pb[one], pb[two]);
  // Same number of records either way; the utterance sits on the last one.
  ASSERT_EQ(a.steps.size(), b.steps.size());
  EXPECT_EQ(a.steps.back().utterances.size(), 1u);
  EXPECT_EQ(b.steps.back().utterances.size(), 1u);
  // Speak factors: one utterance and T silent steps in both alignments, i.e.
  // utterance part = log P(u | ...) + log 0.05 + T log 0.95.
  const double T = static_cast<double>(a.steps.size() - 1);
  const double speak = std::log(0.05) + T * std::log(0.95);
  for (const InferenceRun* r : {&a, &b})
    for (size_t h = 0; h < r->belief->hypotheses().size(); ++h)
      EXPECT_NEAR(r->belief->utterance_log_likelihood(static_cast<int>(h)) -
                      r->steps.back().utterances[0].hypotheses[h].log_likelihood,
                  speak, 1e-9);
}

}  // namespace
}  // namespace clips::inference
