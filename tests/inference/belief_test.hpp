#pragma once
// The includes, helpers and fixtures of the inference tests in belief_test.cpp, shared by
// the files of that name in tests/inference/ and its label folders
// (docs/testing.md, "Labels").
// Belief updates on a hand-made corridor where every number can be worked out
// on paper, plus the do-operator and the three modalities.
#include "domains/builtin/packs.hpp"
#include "engine/runs.hpp"
#include "inference/belief.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <memory>

#include "data/dataset.hpp"
#include "language/listener.hpp"
#include "pddl/parser.hpp"
#include "test_paths.hpp"
#include "dkg_profiles.hpp"

namespace clips::inference {
// Whole plans are replayed through the engine (engine/runs.hpp).
using engine::run_inference;
namespace belief_test {

// One row of five cells: gem1 (red) at x = 1, gem2 (yellow) at x = 5, the
// human and the robot both at x = 3; the human moves first.
const char* kCorridor = R"(
(define (problem corridor) (:domain doors-keys-gems)
  (:objects gem1 gem2 - gem red yellow - color robot - robot human - human)
  (:init (= (walls) (new-bit-matrix false 1 5))
         (= (xloc gem1) 1) (= (yloc gem1) 1) (iscolor gem1 red)
         (= (xloc gem2) 5) (= (yloc gem2) 1) (iscolor gem2 yellow)
         (= (xloc human) 3) (= (yloc human) 1)
         (= (xloc robot) 3) (= (yloc robot) 1)
         (active human) (next-turn human robot) (next-turn robot human)
         (forbidden robot gem1) (forbidden robot gem2))
  (:goal (has human gem1)))
)";

std::shared_ptr<const pddl::Task> corridor_task() {
  auto d = std::make_shared<pddl::Domain>(pddl::load_domain(paths::examples_dir() + "/doors-keys-gems/domain.pddl"));
  auto p = std::make_shared<pddl::Problem>(pddl::parse_problem(*d, kCorridor, "corridor.pddl"));
  return std::make_shared<pddl::Task>(d, p, domains::builtin_pack("doors-keys-gems")->spec().grounding);
}

Belief corridor_belief(const std::shared_ptr<const pddl::Task>& task) {
  std::vector<data::GoalSpec> goals = {{"gem1", "(has human gem1)", ""}, {"gem2", "(has human gem2)", ""}};
  InferenceOptions opts;
  opts.heuristic = "hmax";  // admissible, so the refined values are exact here
  return Belief(task, domains::builtin_pack("doors-keys-gems"), goals, {fixtures::dkg_profile(3), fixtures::dkg_profile(4)}, opts);
}

pddl::ActionId act(const pddl::Task& task, const std::string& text) { return *task.find_action(text); }

// An LM that prefers prompts whose command mentions the colour said in the utterance.
class ColourLm : public lm::LanguageModel {
 public:
  std::string name() const override { return "colour"; }
  std::vector<double> score(const std::vector<lm::ScoreRequest>& batch) override {
    ++calls;
    std::vector<double> out;
    for (const auto& r : batch) {
      const auto q = r.prompt.rfind("Input:");
      const std::string cmd = q == std::string::npos ? "" : r.prompt.substr(q);
      const bool red = r.continuation.find("red") != std::string::npos;
      out.push_back(cmd.find(red ? "red" : "yellow") != std::string::npos ? -1.0 : -6.0);
    }
    return out;
  }
  int calls = 0;
};

// The language-only posterior of one repo plan with an instruction, under the
// given noise and exponent (one cost profile, uniform prior: the posterior is
// the normalised utterance evidence).
std::vector<double> language_only(double noise, double exponent) {
  auto lm = language::make_language_model("embedded");
  const auto ds = data::Dataset::load(paths::source_dir() + "/data/datasets/workshop");
  InferenceOptions o;
  o.utterance_noise = noise;
  o.utterance_exponent = exponent;
  const InferenceRun run = run_inference(ds, ds.plan("3.3.birdhouse"), *lm, o);
  return run.final_posterior(Modality::UtteranceOnly).hypotheses;
}

// The record of the last step that heard an utterance (null: none did).
const UtteranceRecord* last_utterance(const InferenceRun& run) {
  const UtteranceRecord* said = nullptr;
  for (const StepRecord& step : run.steps)
    if (!step.utterances.empty()) said = &step.utterances.front();
  return said;
}

// A plan of one of the repo's datasets, read as clips bench and clips infer
// read it: the embedded model trained on a corpus generated from the
// dataset's own domain.
struct DatasetPlanRun {
  data::Dataset ds;
  InferenceRun run;
  DatasetPlanRun(const std::string& dataset, const std::string& plan)
      : ds(data::Dataset::load(paths::source_dir() + "/data/datasets/" + dataset)),
        run(run_inference(ds, ds.plan(plan), *language::make_dataset_language_model("embedded", {}, ds))) {}
  // The commands the true goal's base hypothesis read the last utterance as
  // (none, failing the test, if nothing was said).
  std::vector<CommandScore> true_goal_commands() const {
    const UtteranceRecord* said = last_utterance(run);
    EXPECT_NE(said, nullptr);
    if (said == nullptr) return {};
    return said->hypotheses[static_cast<size_t>(run.true_goal) * run.profiles.size()].commands;
  }
};

}  // namespace belief_test
using namespace belief_test;
}  // namespace clips::inference
