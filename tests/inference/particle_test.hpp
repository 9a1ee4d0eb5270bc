#pragma once
// The includes, helpers and fixtures of the inference tests in particle_test.cpp, shared by
// the files of that name in tests/inference/ and its label folders
// (docs/testing.md, "Labels").
// Particle (SMC) inference: the filter's bookkeeping on made-up likelihoods,
// then Belief's particle mode against exact enumeration on the hand-made
// corridor and on the repo's example plans.
#include "domains/builtin/packs.hpp"
#include "inference/particle_belief.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <map>
#include <memory>

#include "engine/runs.hpp"
#include "inference/belief.hpp"
#include "language/listener.hpp"
#include "pddl/parser.hpp"
#include "test_paths.hpp"
#include "dkg_profiles.hpp"

namespace clips::inference {
// Whole plans are replayed through the engine (engine/runs.hpp).
using engine::run_inference;
namespace particle_test {

constexpr double kNegInf = -std::numeric_limits<double>::infinity();

ParticleOptions popts(int n, double ess = 0.5, int moves = 2, uint64_t seed = 1) {
  ParticleOptions o;
  o.particles = n;
  o.ess_threshold = ess;
  o.rejuvenation_moves = moves;
  o.seed = seed;
  return o;
}

const ParticleFilter::Sync kNoSync = [](const std::vector<int>&) {};
const ParticleFilter::Current kNone = [] { return std::vector<int>{}; };

// ---------------------------------------------------------------------------
// Belief in particle mode on the corridor of belief_test.cpp: gem1 (red) at
// x = 1, gem2 (yellow) at x = 5, both agents at x = 3.

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

Belief corridor_belief(const std::shared_ptr<const pddl::Task>& task, InferenceOptions opts) {
  std::vector<data::GoalSpec> goals = {{"gem1", "(has human gem1)", ""}, {"gem2", "(has human gem2)", ""}};
  opts.heuristic = "hmax";
  return Belief(task, domains::builtin_pack("doors-keys-gems"), goals, {fixtures::dkg_profile(3), fixtures::dkg_profile(4)},
                opts);
}

// Prefers prompts whose command has the colour the utterance names.
class ColourLm : public lm::LanguageModel {
 public:
  std::string name() const override { return "colour"; }
  std::vector<double> score(const std::vector<lm::ScoreRequest>& batch) override {
    std::vector<double> out;
    for (const auto& r : batch) {
      const auto q = r.prompt.rfind("Input:");
      const std::string cmd = q == std::string::npos ? "" : r.prompt.substr(q);
      const bool red = r.continuation.find("red") != std::string::npos;
      out.push_back(cmd.find(red ? "red" : "yellow") != std::string::npos ? -1.0 : -6.0);
    }
    return out;
  }
};

double tv(const std::vector<double>& p, const std::vector<double>& q) {
  double s = 0;
  for (size_t i = 0; i < p.size(); ++i) s += std::abs(p[i] - q[i]);
  return s / 2;
}

// A fixed observation sequence with actions of both agents and utterances
// in the middle and at the end; returns every step's record.
std::vector<StepRecord> corridor_run(Belief& b, const pddl::Task& task, ColourLm& lm) {
  auto act = [&](const char* a) { return *task.find_action(a); };
  std::vector<StepRecord> steps;
  steps.push_back(b.start(task.initial_state()));
  steps.push_back(b.observe(act("(right human)"), b.state()));
  steps.push_back(b.observe(act("(wait robot)"), b.state(), {"Can you get the yellow one?"}, &lm));
  steps.push_back(b.observe(act("(left human)"), b.state()));
  steps.push_back(b.observe(act("(wait robot)"), b.state()));
  steps.push_back(b.observe(act("(left human)"), b.state()));
  steps.back() = b.hear({"I want the red gem"}, lm, steps.back());
  return steps;
}

// ---------------------------------------------------------------------------
// The repo's example plans with the embedded language model (integration).

}  // namespace particle_test
using namespace particle_test;
}  // namespace clips::inference
