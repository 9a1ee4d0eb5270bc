#include "generate/generate_test.hpp"

namespace clips::generate {
namespace generate_test {
TEST(GenerateDataset, SmallSetLoadsAndEveryPlanChecks) {
  const GeneratedDataset gen = generate_dataset(small(1), &shared_lm());
  ASSERT_EQ(gen.plans.size(), 3u);
  TempDir dir("generate");
  write_dataset(gen, dir.str(), false);
  const auto ds = data::Dataset::load(dir.str());
  EXPECT_TRUE(ds.broken_plans().empty());
  ASSERT_EQ(ds.plans().size(), 3u);
  const auto report = data::validate_dataset(ds);
  EXPECT_EQ(report.failed, 0);
  for (const auto& r : report.results) EXPECT_TRUE(r.ok) << r.plan_id << ": " << r.error;

  for (const GeneratedPlan& g : gen.plans) {
    SCOPED_TRACE(g.id);
    const data::PlanRecord& p = ds.plan(g.id);
    EXPECT_TRUE(g.tag == "keys" || g.tag == "doors");
    EXPECT_EQ(p.tag, g.tag);
    // The loader's true goal is the goal the plan was sampled for, and the
    // completion reaches it and no other gem (validate_dataset above).
    const auto goals = ds.candidate_goals(p);
    EXPECT_EQ(goals.at(static_cast<size_t>(ds.true_goal_index(p))).label, g.goal);
    ASSERT_FALSE(p.completed.actions.empty());
    EXPECT_EQ(p.completed.actions.back().text, "(pickup human " + g.goal + ")");
    EXPECT_EQ(static_cast<int>(p.observed.actions.size()), g.observed_steps);
    EXPECT_EQ(static_cast<int>(p.completed.actions.size()), g.completed_steps);
    // The robot waits until the instruction, as in the paper's observed plans.
    for (const auto& a : p.observed.actions)
      if (a.text.find("robot") != std::string::npos) {
        EXPECT_EQ(a.text, "(wait robot)");
      }
    ASSERT_EQ(p.observed.utterances.size(), 1u);
    EXPECT_EQ(p.observed.utterances[0].text, g.utterance);
    EXPECT_EQ(p.observed.utterances[0].index, g.utterance_step);
    EXPECT_LE(g.utterance_step, g.observed_steps);
    EXPECT_EQ(p.pragmatic_utterance, g.utterance);
    EXPECT_EQ(p.literal_utterance, g.literal_utterance);
    EXPECT_EQ(data::true_options(ds, p), g.options);
    EXPECT_FALSE(g.command.empty()) << "every gem needs help here, so the speaker has something to ask";
  }
  EXPECT_TRUE(gen.files.count("problems/1.txt"));
  EXPECT_TRUE(gen.files.count("generation.json"));
}

TEST(GenerateDataset, TheSeedDecidesEveryByte) {
  GenerateOptions o = small(5);
  o.plans_per_problem = 1;
  const auto a = generate_dataset(o, &shared_lm());
  const auto b = generate_dataset(o, &shared_lm());
  EXPECT_EQ(a.files, b.files);
  o.seed = 6;
  const auto c = generate_dataset(o, &shared_lm());
  EXPECT_NE(a.files.at("problems/1.pddl"), c.files.at("problems/1.pddl"));
}

}  // namespace generate_test

}  // namespace clips::generate
