#include "generate/generate_test.hpp"

namespace clips::generate {
namespace generate_test {
TEST(GenerateDataset, TheSpeakerPlansAsInferenceDoes) {
  // The instruction's command is drawn from the commands the CLIPS speaker
  // model lists for the true hypothesis with the policy inference holds when
  // it hears the instruction, not one that has also learned from the rest
  // of the sampled sequence. Inference on the prefix up to the instruction
  // ends in that state with that policy, so its commands must hold the one
  // drawn (or be empty when the speaker had nothing to ask).
  GenerateOptions o = small(3);
  o.map.width = o.map.height = 8;
  o.map.counts = {{"gem", 3}, {"key", 2}, {"door", 2}};
  o.problems = 2;
  o.plans_per_problem = 3;
  // Small lookahead budgets: partial searches, so a policy's commands
  // depend on what it has been refined on.
  o.refine_nodes = 40;
  inference::InferenceOptions io;
  io.refine.max_nodes = o.refine_nodes;
  const GeneratedDataset gen = generate_dataset(o, &shared_lm());
  TempDir dir("generate-speaker");
  write_dataset(gen, dir.str(), false);
  const auto ds = data::Dataset::load(dir.str());
  int with_actions_before = 0;
  for (const GeneratedPlan& g : gen.plans) {
    SCOPED_TRACE(g.id + " (instruction after " + std::to_string(g.utterance_step) + " actions)");
    data::PlanRecord prefix = ds.plan(g.id);
    ASSERT_EQ(prefix.observed.utterances.size(), 1u);
    prefix.observed.actions.resize(static_cast<size_t>(g.utterance_step));
    with_actions_before += g.utterance_step > 0;
    std::vector<std::string> listed;
    for (const auto& c : true_speaker_commands(ds, prefix, io)) listed.push_back(c.llm_form());
    if (g.command.empty()) {
      EXPECT_TRUE(listed.empty());
    } else {
      EXPECT_NE(std::find(listed.begin(), listed.end(), g.command), listed.end()) << g.command;
    }
  }
  EXPECT_GT(with_actions_before, 0) << "no plan checks a speaker who has acted first";
}

TEST(GenerateDataset, TheInstructionComesWhereTheSpeakerHasSomethingToAsk) {
  // The instruction's step is drawn among the observed steps at which the
  // speaker model lists commands for the true hypothesis; an instruction
  // for no command is left only to plans where no step has one. Checked by
  // replaying inference on every prefix of a plan that came out without a
  // command. (On this seed, drawing the step among all steps gave plan
  // 2.1.keys an instruction at a step with nothing to ask, though earlier
  // steps had commands.)
  GenerateOptions o = small(5);
  o.map.width = o.map.height = 9;
  o.map.counts = {{"gem", 4}, {"key", 2}, {"door", 2}};
  o.problems = 2;
  o.plans_per_problem = 3;
  const GeneratedDataset gen = generate_dataset(o, &shared_lm());
  TempDir dir("generate-asks");
  write_dataset(gen, dir.str(), false);
  const auto ds = data::Dataset::load(dir.str());
  auto asks_at = [&](const GeneratedPlan& g, int j) {
    data::PlanRecord prefix = ds.plan(g.id);
    prefix.observed.actions.resize(static_cast<size_t>(j));
    // Heard after j actions: inference then refines at s_j, as the speaker's plan is.
    prefix.observed.utterances.at(0).index = j;
    return !true_speaker_commands(ds, prefix).empty();
  };
  int with_command = 0;
  for (const GeneratedPlan& g : gen.plans) {
    SCOPED_TRACE(g.id);
    if (!g.command.empty()) {
      ++with_command;
      EXPECT_TRUE(asks_at(g, g.utterance_step));
      continue;
    }
    for (int j = 0; j <= g.observed_steps; ++j) EXPECT_FALSE(asks_at(g, j)) << "the speaker could ask after " << j;
  }
  EXPECT_GT(with_command, 0);
}

TEST(GenerateDataset, ImpossibleParametersAreClearErrors) {
  GenerateOptions crowded = small(1);
  crowded.map.width = crowded.map.height = 3;
  crowded.map.counts = {{"gem", 2}, {"key", 3}, {"door", 3}};
  EXPECT_NE(error_of(crowded).find("need 10 cells, but a 3x3 map has only 9"), std::string::npos) << error_of(crowded);

  GenerateOptions walled = small(1);
  walled.map.width = walled.map.height = 5;
  walled.map.counts = {{"gem", 1}, {"key", 4}, {"door", 4}};
  walled.problem_attempts = 20;
  const std::string e = error_of(walled);
  EXPECT_NE(e.find("could not generate a 5x5 map, 4 doors, 1 gem, 4 keys"), std::string::npos) << e;
  EXPECT_NE(e.find("20 attempts"), std::string::npos) << e;

  GenerateOptions none = small(1);
  none.plans_per_problem = 0;
  EXPECT_NE(error_of(none).find("at least one problem and one plan"), std::string::npos);
}

TEST(GenerateDataset, RefusesToWriteOverAnotherFolderWithoutForce) {
  TempDir dir("generate-force");
  { std::ofstream(dir.path / "notes.txt") << "mine\n"; }
  GeneratedDataset gen;
  gen.files["domain.pddl"] = "(define (domain x))\n";
  try {
    write_dataset(gen, dir.str(), false);
    FAIL() << "expected an InputError";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("--force"), std::string::npos) << e.what();
  }
  std::filesystem::create_directories(dir.path / "plans" / "observed");
  { std::ofstream(dir.path / "plans" / "observed" / "9.1.keys.pddl") << "(wait human)\n"; }
  write_dataset(gen, dir.str(), true);
  EXPECT_FALSE(std::filesystem::exists(dir.path / "plans" / "observed" / "9.1.keys.pddl")) << "stale plan left";
  EXPECT_TRUE(std::filesystem::exists(dir.path / "notes.txt"));
  EXPECT_EQ(testing::read_text(dir.path / "domain.pddl"), "(define (domain x))\n");
}

}  // namespace generate_test

}  // namespace clips::generate
