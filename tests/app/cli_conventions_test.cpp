#include "app/cli_conventions_test.hpp"

namespace clips::eval {
namespace cli_conventions_test {
TEST(CliVersion, PrintsTheProjectVersion) {
  const auto r = run_stdout(clips() + "--version");
  EXPECT_EQ(r.status, 0) << r.out;
  EXPECT_TRUE(std::regex_search(r.out, std::regex(R"(^clips \d+\.\d+\.\d+)"))) << r.out;
}

// Installed, the command is clips-assist (Debian's /usr/bin/clips is the
// expert system): the name it was run as is the one in --version, --help
// and every message, taken from argv[0].
TEST(CliVersion, SaysTheNameItWasRunAs) {
  testing::TempDir tmp("name");
  const fs::path link = tmp.path / "clips-assist";
  fs::create_symlink(fs::absolute(clips_binary()), link);
  auto r = run_stdout(link.string() + " --version");
  EXPECT_EQ(r.status, 0) << r.out;
  EXPECT_TRUE(std::regex_search(r.out, std::regex(R"(^clips-assist \d+\.\d+\.\d+)"))) << r.out;
  r = run_stdout(link.string() + " infer --help");
  EXPECT_TRUE(contains(r.out, "Usage: clips-assist infer")) << r.out;
  r = run(link.string() + " infer --plan e1.1.keys --dataset " + (tmp.path / "none").string());
  EXPECT_EQ(r.status, 3) << r.out;
  EXPECT_EQ(r.out.rfind("clips-assist: error: ", 0), 0u) << r.out;
  r = run(link.string() + " frobnicate");
  EXPECT_EQ(r.out.rfind("clips-assist: unknown subcommand 'frobnicate'", 0), 0u) << r.out;
}

TEST(BenchFilesTest, NoPaperColumnBesideAnotherDataset) {
  BenchFiles b(examples_dkg(), "--plans e1.1.keys --methods clips");
  ASSERT_EQ(b.result.status, 0) << b.result.out;
  EXPECT_FALSE(contains(b.result.out, "paper")) << b.result.out;
  EXPECT_TRUE(contains(b.result.out, "ours")) << b.result.out;
}

}  // namespace cli_conventions_test

}  // namespace clips::eval
