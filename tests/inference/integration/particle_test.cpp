#include "inference/particle_test.hpp"

namespace clips::inference {
namespace particle_test {
TEST(ParticleExamples, MatchExactOnTheRepoExamples) {
  std::shared_ptr<lm::LanguageModel> lm;
  try {
    lm = language::make_language_model("embedded");
  } catch (const std::exception& e) {
    GTEST_SKIP() << "embedded LM unavailable: " << e.what();
  }
  const auto ds = data::Dataset::load(paths::examples_dir() + "/doors-keys-gems");
  for (const auto& plan : ds.plans()) {
    const InferenceRun exact = run_inference(ds, plan, *lm);
    InferenceOptions po;
    po.particles = 256;  // 32 per hypothesis
    const InferenceRun run = run_inference(ds, plan, *lm, po);
    ASSERT_EQ(run.steps.size(), exact.steps.size());
    double worst = 0;
    for (size_t t = 0; t < exact.steps.size(); ++t)
      for (Modality m : kModalities) worst = std::max(worst, tv(exact.steps[t][m].goals, run.steps[t][m].goals));
    std::printf("%s: worst step TV %.4f, final CLIPS TV %.4f, refinements %zu / %zu\n", plan.id.c_str(), worst,
                tv(exact.final_posterior(Modality::Both).goals, run.final_posterior(Modality::Both).goals),
                run.belief->refinements(), exact.belief->refinements());
    EXPECT_LT(worst, 0.1) << plan.id;
    // The true goal is the particle posterior's most likely one when it is the exact one's.
    const auto& pe = exact.final_posterior(Modality::Both).goals;
    const auto& pp = run.final_posterior(Modality::Both).goals;
    EXPECT_EQ(std::max_element(pe.begin(), pe.end()) - pe.begin(), std::max_element(pp.begin(), pp.end()) - pp.begin())
        << plan.id;
  }
}

}  // namespace particle_test

}  // namespace clips::inference
