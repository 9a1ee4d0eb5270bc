// How a posterior becomes the assistant's hypotheses (engine/hypotheses.hpp).
#include "engine/hypotheses.hpp"

#include <gtest/gtest.h>

#include "data/dataset.hpp"
#include "engine/runs.hpp"
#include "language/listener.hpp"
#include "test_paths.hpp"

namespace clips::engine {
namespace {

// An alone twin says how the principal chooses, not what help costs: the
// assistant counts its weight with the same goal under the twin's base
// profile, so Q_MDP values every goal with the cooperative costs.
TEST(AssistantWeights, ATwinsWeightMovesToItsBase) {
  auto lm = language::make_language_model("embedded");
  const auto ds = data::Dataset::load(paths::source_dir() + "/data/datasets/lab");
  const inference::InferenceRun run = engine::run_inference(ds, ds.plan("5.2.digestion"), *lm);
  const inference::Belief& belief = *run.belief;
  ASSERT_EQ(belief.profiles().size(), 2u);
  ASSERT_EQ(belief.profiles()[1].twin_of, 0);
  for (inference::Modality m : {inference::Modality::Both, inference::Modality::ActionOnly}) {
    const inference::Posterior& post = run.final_posterior(m);
    const std::vector<double> w = assistant_weights(belief, post);
    ASSERT_EQ(w.size(), post.hypotheses.size());
    double total = 0, twins = 0;
    for (size_t h = 0; h < w.size(); ++h) total += w[h];
    EXPECT_NEAR(total, 1.0, 1e-9);
    for (size_t h = 0; h < w.size(); ++h) {
      const inference::Hypothesis& hyp = belief.hypotheses()[h];
      if (hyp.profile == 1) {
        EXPECT_EQ(w[h], 0.0);
        twins += post.hypotheses[h];
        continue;
      }
      // The base holds its own weight and its twin's: the goal's marginal.
      EXPECT_NEAR(w[h], post.goals[static_cast<size_t>(hyp.goal)], 1e-9);
    }
    EXPECT_GT(twins, 0.5);  // the twins held most of it: the test moves something
    const auto hyps = assistant_hypotheses(belief, post, std::vector<std::shared_ptr<const assist::Request>>(w.size()));
    for (size_t h = 0; h < w.size(); ++h) EXPECT_EQ(hyps[h].weight, w[h]);
  }
}

}  // namespace
}  // namespace clips::engine
