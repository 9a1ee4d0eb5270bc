#include "app/cli_input_test.hpp"

namespace clips::eval {
namespace cli_input_test {
TEST(CliNumbers, GoodValuesStillParse) {
  auto r = run(clips_binary() + " show --dataset " + examples_dkg() + " --plan e1.1.keys --step 0");
  EXPECT_EQ(r.status, 0) << r.out;
  EXPECT_TRUE(contains(r.out, "step 0/")) << r.out;
  r = run(clips_binary() + " plan --dataset " + examples_dkg() +
          " --problem e1 --max-nodes 100000 --max-seconds 30 --time-limit 30");
  EXPECT_EQ(r.status, 0) << r.out;
  EXPECT_TRUE(contains(r.out, "status success")) << r.out;
}

TEST(CliShow, NegativeStepIsRejectedNotTheLastStep) {
  auto r = run(clips_binary() + " show --dataset " + examples_dkg() + " --plan e1.1.keys --step -5");
  EXPECT_NE(r.status, 0) << r.out;
  EXPECT_FALSE(contains(r.out, "plan e1.1.keys (problem")) << r.out;
}

TEST(CliMain, UnknownSubcommandIsNamedWithTheValidOnes) {
  auto r = run(clips_binary() + " foo");
  EXPECT_NE(r.status, 0) << r.out;
  EXPECT_TRUE(contains(r.out, "unknown subcommand 'foo'")) << r.out;
  for (const char* sub : {"validate", "plan", "bench", "render"}) EXPECT_TRUE(contains(r.out, sub)) << r.out;
  r = run(clips_binary());
  EXPECT_NE(r.status, 0) << r.out;
  EXPECT_TRUE(contains(r.out, "subcommand is required")) << r.out;
}

TEST(CliListen, EmptyLiteralUtteranceFileIsNamed) {
  testing::TempDir tmp("listen-empty");
  const auto ds = tmp.path / "dkg";
  std::filesystem::copy(examples_dkg(), ds, std::filesystem::copy_options::recursive);
  const auto lit = ds / "utterances" / "literal" / "e1.1.keys.txt";
  std::ofstream(lit, std::ios::trunc).close();
  auto r = run(clips_binary() + " listen --dataset " + ds.string() + " --plan e1.1.keys");
  EXPECT_NE(r.status, 0) << r.out;
  EXPECT_TRUE(contains(r.out, "utterances/literal/e1.1.keys.txt is empty")) << r.out;
  EXPECT_FALSE(contains(r.out, "--utterance is empty")) << r.out;
}

}  // namespace cli_input_test

}  // namespace clips::eval
