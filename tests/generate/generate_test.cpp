// `clips generate` as a library (generate/generate.hpp): a small generated set
// loads, every plan checks and reaches its recorded goal, the seed alone
// decides the bytes, and impossible parameters are clear errors.
#include "generate/generate.hpp"

#include <gtest/gtest.h>

#include <algorithm>

#include "data/dataset.hpp"
#include "data/validate.hpp"
#include "inference/belief.hpp"
#include "inference/utterance_model.hpp"
#include "eval/support.hpp"
#include "pddl/parser.hpp"
#include "util/error.hpp"

namespace clips::eval {
namespace {

using testing::TempDir;

GenerateOptions small(uint64_t seed) {
  GenerateOptions o;
  o.domain_file = paths::source_dir() + "/data/domains/doors-keys-gems/domain.pddl";
  o.map.width = 7;
  o.map.height = 7;
  o.map.counts = {{"gem", 2}, {"key", 1}, {"door", 1}};
  o.problems = 1;
  o.plans_per_problem = 3;
  o.seed = seed;
  return o;
}

// One embedded model for every test, trained (or loaded from the cache) once.
lm::LanguageModel& shared_lm() {
  static const std::shared_ptr<lm::LanguageModel> lm = [] {
    const auto domain = pddl::load_domain(small(0).domain_file);
    return language::make_domain_language_model("embedded", {}, *domains::find_pack(domain), domain, {});
  }();
  return *lm;
}

// For runs that fail before any utterance is scored.
class NoLanguageModel : public lm::LanguageModel {
 public:
  std::string name() const override { return "none"; }
  std::vector<double> score(const std::vector<lm::ScoreRequest>& batch) override {
    return std::vector<double>(batch.size(), 0.0);
  }
};

std::string error_of(const GenerateOptions& o) {
  try {
    NoLanguageModel lm;
    generate_dataset(o, &lm);
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

// What the CLIPS speaker model lists for the true hypothesis after inference
// on `prefix` (the state and the policy the observer holds then).
std::vector<commands::Command> true_speaker_commands(const data::Dataset& ds, const data::PlanRecord& prefix,
                                                     const inference::InferenceOptions& io = {}) {
  const auto run = inference::run_inference(ds, prefix, shared_lm(), io);
  const auto& b = *run.belief;
  for (size_t h = 0; h < b.hypotheses().size(); ++h)
    if (b.hypotheses()[h].goal == run.true_goal && b.hypotheses()[h].profile == run.true_profile) {
      const inference::UtteranceModel speaker(ds.task(prefix.problem_id), ds.pack_ptr());
      return speaker.commands_at(b.policies()[h], b.state());
    }
  ADD_FAILURE() << prefix.id << ": no hypothesis is the true one";
  return {};
}

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

}  // namespace
}  // namespace clips::eval
