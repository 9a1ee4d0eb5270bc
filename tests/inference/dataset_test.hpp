#pragma once
// The includes, helpers and fixtures of the inference tests in dataset_test.cpp, shared by
// the files of that name in tests/inference/ and its label folders
// (docs/testing.md, "Labels").
// Inference on the paper's datasets (skipped when ../shared/dataset is absent).
#include <gtest/gtest.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <memory>

#include "engine/runs.hpp"
#include "inference/belief.hpp"
#include "pddl/plan.hpp"
#include "domains/vh/vh_value.hpp"
#include "language/listener.hpp"
#include "test_paths.hpp"

namespace clips::inference {
// Whole plans are replayed through the engine (engine/runs.hpp).
using engine::run_inference;
namespace dataset_test {

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

}  // namespace dataset_test
using namespace dataset_test;
}  // namespace clips::inference
