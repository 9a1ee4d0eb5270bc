// Two inferences at once, as `clips bench --jobs 2` runs them: each on its own
// thread with its own dataset, both refining their hypotheses on a worker
// pool, and both scoring utterances through one language model, whose caches
// (trained blocks, bound commands, respellings, memoised scores) then fill
// from two threads. Small enough for `make test-tsan`.
#include <gtest/gtest.h>

#include <cstdio>
#include <memory>
#include <string>
#include <thread>
#include <vector>

#include "engine/runs.hpp"
#include "inference/belief.hpp"
#include "language/listener.hpp"
#include "test_paths.hpp"

namespace clips::inference {
// Whole plans are replayed through the engine (engine/runs.hpp).
using engine::run_inference;
namespace {

std::shared_ptr<lm::LanguageModel> fresh_embedded_lm() {
  try {
    return language::make_language_model("embedded");
  } catch (const std::exception& e) {
    std::printf("embedded LM unavailable: %s\n", e.what());
    return nullptr;
  }
}

InferenceRun infer(const std::string& plan_id, lm::LanguageModel& lm) {
  // Tasks compile goals into their own pools, so each run loads its own copy.
  const auto ds = data::Dataset::load(paths::examples_dir() + "/doors-keys-gems");
  InferenceOptions options;
  options.threads = 2;
  return run_inference(ds, ds.plan(plan_id), lm, options);
}

TEST(ConcurrentInference, TwoPlansAtOnceSharingOneLanguageModelMatchOneAtATime) {
  const std::vector<std::string> plans = {"e1.1.keys", "e2.1.doors"};
  auto shared = fresh_embedded_lm();
  if (!shared) GTEST_SKIP() << "no embedded LM";
  std::vector<InferenceRun> together(plans.size());
  std::vector<std::string> errors(plans.size());
  {
    std::vector<std::thread> threads;
    for (size_t i = 0; i < plans.size(); ++i)
      threads.emplace_back([&, i] {
        try {
          together[i] = infer(plans[i], *shared);
        } catch (const std::exception& e) {
          errors[i] = e.what();
        }
      });
    for (auto& t : threads) t.join();
  }
  for (size_t i = 0; i < plans.size(); ++i) {
    ASSERT_EQ(errors[i], "") << plans[i];
    // A fresh model per plan: its caches see this plan alone.
    auto own = fresh_embedded_lm();
    ASSERT_TRUE(own);
    const InferenceRun alone = infer(plans[i], *own);
    ASSERT_EQ(together[i].steps.size(), alone.steps.size()) << plans[i];
    ASSERT_GT(alone.steps.size(), 1u) << plans[i];
    bool heard = false;
    for (size_t t = 0; t < alone.steps.size(); ++t) {
      heard = heard || !alone.steps[t].utterances.empty();
      for (Modality m : kModalities)
        EXPECT_EQ(together[i].steps[t][m].hypotheses, alone.steps[t][m].hypotheses) << plans[i] << " step " << t;
    }
    EXPECT_TRUE(heard) << plans[i] << ": the language model was never asked";
  }
}

}  // namespace
}  // namespace clips::inference
