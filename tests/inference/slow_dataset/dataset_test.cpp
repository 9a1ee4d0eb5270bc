#include "domains/builtin/packs.hpp"
#include "inference/dataset_test.hpp"

namespace clips::inference {
namespace dataset_test {
TEST(DkgDataset, AllPlansThreeModalities) {
  if (!paths::have_shared_dataset()) GTEST_SKIP() << "no dataset";
  // With h_max instead of the MST heuristic the 2^18-node refinements take
  // ~18 min for all plans (more than ctest's 900 s limit): opt in explicitly.
  if (domains::builtin_pack("doors-keys-gems")->spec().inference.heuristic != "dkg-mst" && !std::getenv("CLIPS_INFER_ALL_PLANS"))
    GTEST_SKIP() << "dkg-mst not registered yet; set CLIPS_INFER_ALL_PLANS=1 to run with h_max";
  auto lm = embedded_lm();
  if (!lm) GTEST_SKIP() << "no embedded LM";
  auto ds = data::Dataset::load(paths::dkg_dataset());
  std::printf("%-14s %8s %8s %8s %6s %8s\n", "plan", "both", "action", "utter", "steps", "seconds");
  double total = 0, sum[3] = {0, 0, 0}, min_both = 1;
  int n = 0, both_at_least_action = 0;
  std::vector<double> step_times;
  for (const auto& plan : ds.plans()) {
    const InferenceRun run = run_inference(ds, plan, *lm);
    for (const auto& st : run.steps) {
      for (Modality m : kModalities) expect_sane(st[m]);
      step_times.push_back(st.seconds);
    }
    const double p[3] = {run.p_true_goal(Modality::Both), run.p_true_goal(Modality::ActionOnly),
                         run.p_true_goal(Modality::UtteranceOnly)};
    std::printf("%-14s %8.4f %8.4f %8.4f %6zu %8.2f\n", plan.id.c_str(), p[0], p[1], p[2], run.steps.size(),
                run.seconds);
    std::fflush(stdout);
    if (plan.evaluated) {
      for (int i = 0; i < 3; ++i) sum[i] += p[i];
      ++n;
      if (p[0] >= p[1] - 1e-9) ++both_at_least_action;
      min_both = std::min(min_both, p[0]);
    }
    total += run.seconds;
  }
  std::sort(step_times.begin(), step_times.end());
  std::printf("mean over %d evaluated plans: both %.4f  action %.4f  utterance %.4f; total %.1f s, median step %.4f s\n",
              n, sum[0] / n, sum[1] / n, sum[2] / n, total, step_times[step_times.size() / 2]);
  // What the README and the paper claim (Table 1, P(g_true) of the three
  // inverse planners: 0.74 / 0.55 / 0.31 in the paper, 0.79 / 0.56 / 0.33
  // here), with margins: CLIPS ahead of language alone ahead of actions alone.
  ASSERT_EQ(n, 24);
  const double both = sum[0] / n, action = sum[1] / n, utterance = sum[2] / n;
  EXPECT_GE(both, 0.70);
  EXPECT_GE(utterance, 0.45);
  EXPECT_LE(utterance, 0.70);
  EXPECT_GE(action, 0.22);
  EXPECT_LE(action, 0.45);
  EXPECT_GT(both, utterance + 0.1);
  EXPECT_GT(utterance, action + 0.1);
  // Per plan: language on top of the actions helps (measured on all 24 plans;
  // two may slip) and never leaves the true goal unlikely.
  EXPECT_GE(both_at_least_action, n - 2);
  EXPECT_GE(min_both, 0.4);
}

}  // namespace dataset_test

}  // namespace clips::inference
