#include "inference/dataset_test.hpp"

namespace clips::inference {
namespace dataset_test {
TEST(ParallelRefinement, SameBeliefOnAnyNumberOfThreads) {
  // The project's own examples (always present): every step's posterior and
  // every policy's tables must not depend on how many threads refine them.
  auto lm = embedded_lm();
  if (!lm) GTEST_SKIP() << "no embedded LM";
  auto ds = data::Dataset::load(paths::examples_dir() + "/doors-keys-gems");
  int compared = 0;
  for (const auto& plan : ds.plans()) {
    InferenceOptions one, two;
    two.threads = 2;
    const InferenceRun a = run_inference(ds, plan, *lm, one);
    const InferenceRun b = run_inference(ds, plan, *lm, two);
    ASSERT_EQ(a.steps.size(), b.steps.size());
    for (size_t t = 0; t < a.steps.size(); ++t)
      for (Modality m : kModalities) EXPECT_EQ(a.steps[t][m].hypotheses, b.steps[t][m].hypotheses) << plan.id;
    for (size_t h = 0; h < a.policies().size(); ++h) {
      EXPECT_EQ(a.policies()[h].table_size(), b.policies()[h].table_size());
      EXPECT_EQ(a.policies()[h].tree_size(), b.policies()[h].tree_size());
      EXPECT_EQ(a.policies()[h].value(a.belief->state()), b.policies()[h].value(b.belief->state()));
    }
    ++compared;
  }
  EXPECT_GE(compared, 4);
}

}  // namespace dataset_test

}  // namespace clips::inference
