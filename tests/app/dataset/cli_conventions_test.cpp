#include "app/cli_conventions_test.hpp"

namespace clips::eval {
namespace cli_conventions_test {
TEST(BenchFilesTest, PaperColumnBesideThePapersDataset) {
  if (!clips::paths::have_shared_dataset()) GTEST_SKIP() << "shared dataset not found";
  BenchFiles b(clips::paths::dkg_dataset(), "--plans 1.1.keys --methods clips");
  ASSERT_EQ(b.result.status, 0) << b.result.out;
  EXPECT_TRUE(contains(b.result.out, "paper")) << b.result.out;
  EXPECT_TRUE(contains(b.result.out, "0.74 (0.05)")) << b.result.out;  // the paper's CLIPS P(g_true)
}

TEST(BenchFilesTest, ACopyWithOtherProblemsIsNotThePapers) {
  if (!clips::paths::have_shared_dataset()) GTEST_SKIP() << "shared dataset not found";
  testing::TempDir tmp("not-paper");
  const fs::path dir = tmp.path / "doors-keys-gems";
  fs::copy(clips::paths::dkg_dataset(), dir, fs::copy_options::recursive);
  std::ofstream(dir / "problems/1.pddl", std::ios::app) << "\n; edited\n";
  const auto r = run(clips() + "bench --dataset " + dir.string() + " --plans 1.1.keys --methods clips --no-progress");
  ASSERT_EQ(r.status, 0) << r.out;
  EXPECT_FALSE(contains(r.out, "paper")) << r.out;
}

TEST(CliObservations, OnThePapersDataset) {
  if (!clips::paths::have_shared_dataset()) GTEST_SKIP() << "shared dataset not found";
  const std::string ds = " --dataset " + clips::paths::dkg_dataset();
  const auto ref = run_stdout(clips() + "infer" + ds + " --plan 2.1.keys --json");
  ASSERT_EQ(ref.status, 0);
  const auto adhoc = run_stdout(clips() + "infer" + ds + " --problem 2 --actions " + clips::paths::dkg_dataset() +
                                "/plans/observed/2.1.keys.pddl --json");
  ASSERT_EQ(adhoc.status, 0) << adhoc.out;
  EXPECT_EQ(untimed_steps(ref.out), untimed_steps(adhoc.out));
}

}  // namespace cli_conventions_test

}  // namespace clips::eval
