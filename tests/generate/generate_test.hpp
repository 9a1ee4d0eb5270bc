#pragma once
// The includes, helpers and fixtures of the generate tests in generate_test.cpp, shared by
// the files of that name in tests/generate/ and its label folders
// (docs/testing.md, "Labels").
// `clips generate` as a library (generate/generate.hpp): a small generated set
// loads, every plan checks and reaches its recorded goal, the seed alone
// decides the bytes, and impossible parameters are clear errors.
#include "domains/builtin/packs.hpp"
#include "engine/runs.hpp"
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

namespace clips::generate {
namespace testing = eval::testing;  // the CLI test helpers (eval/support.hpp)
namespace generate_test {

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
  const auto run = engine::run_inference(ds, prefix, shared_lm(), io);
  const auto& b = *run.belief;
  for (size_t h = 0; h < b.hypotheses().size(); ++h)
    if (b.hypotheses()[h].goal == run.true_goal && b.hypotheses()[h].profile == run.true_profile) {
      const inference::UtteranceModel speaker(ds.task(prefix.problem_id), ds.pack_ptr());
      return speaker.commands_at(b.policies()[h], b.state());
    }
  ADD_FAILURE() << prefix.id << ": no hypothesis is the true one";
  return {};
}

}  // namespace generate_test
using namespace generate_test;
}  // namespace clips::generate
