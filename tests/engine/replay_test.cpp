// Recorded observations replayed through the engine's own steps
// (Engine::replay, engine::run_inference): the batch runs and the live
// session are one loop, so what the one does the other can take back.
#include <gtest/gtest.h>

#include <memory>

#include "data/dataset.hpp"
#include "engine/engine.hpp"
#include "engine/json.hpp"
#include "engine/runs.hpp"
#include "inference/belief.hpp"
#include "language/listener.hpp"
#include "pddl/plan.hpp"
#include "test_paths.hpp"

namespace clips::engine {
namespace {

std::string examples_dkg() { return paths::examples_dir() + "/doors-keys-gems"; }

struct Fixture {
  std::shared_ptr<const data::Dataset> ds =
      std::make_shared<const data::Dataset>(data::Dataset::load(examples_dkg()));
  std::shared_ptr<lm::LanguageModel> lm = language::make_language_model("embedded");
  const data::PlanRecord& plan = ds->plan("e2.2.keys");

  Problem problem() const { return dataset_problem(ds, "doors-keys-gems", plan.problem_id, &plan); }
  // The plan's first `n` actions with an instruction heard after `k` of them.
  pddl::PlanFile observed(size_t n, int k) const {
    pddl::PlanFile f = plan.observed;
    f.actions.resize(n);
    f.utterances = {{"Can you get me the red key?", k, {}}};
    return f;
  }
  inference::InferenceOptions after() const {
    inference::InferenceOptions io;
    io.utterance_timing = inference::UtteranceTiming::After;
    return io;
  }
};

nlohmann::json posteriors(const Engine& e) {
  nlohmann::json j;
  for (Method m : {Method::Clips, Method::LanguageOnly, Method::ActionOnly}) j.push_back(to_json(e.posterior(m), m));
  return j;
}

TEST(ReplayedPlan, TakingBackTheLastMoveGivesTheReplayWithoutIt) {
  Fixture f;
  ASSERT_GE(f.plan.observed.actions.size(), 6u);
  // The actions alternate human, robot; the last one is the robot's, so undo
  // takes back the human's move before it with it. An instruction said after
  // 3 actions is scored in the step of the 4th, which stays.
  Engine whole = Engine::replay(f.problem(), {}, f.after(), f.lm, f.observed(6, 3));
  ASSERT_EQ(whole.t(), 6);
  ASSERT_TRUE(whole.undo());
  EXPECT_EQ(whole.t(), 4);
  EXPECT_EQ(posteriors(whole), posteriors(Engine::replay(f.problem(), {}, f.after(), f.lm, f.observed(4, 3))));
}

TEST(ReplayedPlan, AnInstructionWhoseNextMoveIsTakenBackIsHeardWhereItWasSaid) {
  Fixture f;
  // Said after 4 actions, scored in the 5th's step; with the 5th taken back
  // it is heard in s_4, as in a replay that ends there.
  Engine whole = Engine::replay(f.problem(), {}, f.after(), f.lm, f.observed(6, 4));
  ASSERT_TRUE(whole.undo());
  const Engine heard = Engine::replay(f.problem(), {}, f.after(), f.lm, f.observed(4, 4));
  EXPECT_EQ(whole.t(), 4);
  EXPECT_EQ(posteriors(whole), posteriors(heard));
  // The next undo takes the instruction back alone.
  ASSERT_TRUE(whole.undo());
  const Engine unheard = Engine::replay(f.problem(), {}, f.after(), f.lm, f.observed(4, 99));
  EXPECT_EQ(whole.t(), 4);
  EXPECT_EQ(posteriors(whole), posteriors(unheard));
  EXPECT_NE(posteriors(heard), posteriors(unheard));  // the instruction moved the posterior
}

TEST(ReplayedPlan, TheBatchRunIsTheEnginesRecords) {
  Fixture f;
  const inference::InferenceRun run = run_inference(*f.ds, f.plan, *f.lm, f.after());
  Engine e = Engine::replay(f.problem(), {}, f.after(), f.lm, f.plan.observed);
  ASSERT_EQ(run.steps.size(), e.records().size());
  ASSERT_EQ(run.steps.size(), f.plan.observed.actions.size() + 1);
  for (size_t t = 0; t < run.steps.size(); ++t) {
    EXPECT_EQ(run.steps[t].action, e.records()[t].action);
    EXPECT_EQ(run.steps[t][inference::Modality::Both].goals, e.records()[t][inference::Modality::Both].goals);
  }
  EXPECT_EQ(run.true_goal, f.ds->true_goal_index(f.plan));
}

TEST(ReplayedPlan, AnInstructionBeforeAnActionIsCheckedBeforeAnythingChanges) {
  Fixture f;
  Engine e(f.problem(), {}, f.lm);
  const auto first = e.task().find_action(f.plan.observed.actions[0].text);
  ASSERT_TRUE(first.has_value());
  EXPECT_THROW(e.observe(*first, std::vector<std::string>{""}), InputError);
  EXPECT_EQ(e.t(), 0);
  EXPECT_TRUE(e.events().empty());
  e.observe(*first, std::vector<std::string>{"Can you get me the red key?"});
  ASSERT_EQ(e.events().size(), 2u);
  EXPECT_TRUE(e.events()[0].utterance);
  EXPECT_EQ(e.events()[0].scored, Engine::Event::Scored::WithNextAction);
  ASSERT_EQ(e.trace().back().utterances.size(), 1u);
}

TEST(ReplayedPlan, AnActionThatIsNotApplicableStopsTheReplayNamingIt) {
  Fixture f;
  pddl::PlanFile bad = f.plan.observed;
  bad.actions.insert(bad.actions.begin(), pddl::PlanLine{"(pickup human no-such-key)", SourceLoc{"plan", 1, 1}});
  EXPECT_THROW(Engine::replay(f.problem(), {}, f.after(), f.lm, bad), InputError);
}

}  // namespace
}  // namespace clips::engine
