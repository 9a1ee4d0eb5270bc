// `--particles` on `clips infer` and `clips bench`, and `clips bench
// particles` (the particle-versus-exact evaluation), on the repo's examples.
#include <gtest/gtest.h>

#include <fstream>
#include <nlohmann/json.hpp>

#include "eval/support.hpp"

namespace clips::eval {
namespace {

using testing::clips_binary;
using testing::contains;
using testing::examples_dkg;

TEST(ParticleCli, BadValuesAreRefused) {
  const std::string infer = clips_binary() + " infer --dataset " + examples_dkg() + " --plan e1.1.keys ";
  const std::string bench = clips_binary() + " bench particles --dataset " + examples_dkg() + " ";
  struct Case { std::string cmd, option; };
  const std::vector<Case> cases = {
      {infer + "--particles -1", "--particles"},
      {infer + "--particles many", "--particles"},
      {infer + "--particles 2000000", "--particles"},
      {infer + "--ess-threshold 1.5", "--ess-threshold"},
      {infer + "--ess-threshold nan", "--ess-threshold"},
      {infer + "--rejuvenation-moves -2", "--rejuvenation-moves"},
      {infer + "--particle-seed -1", "--particle-seed"},
      {infer + "--particle-filters some", "--particle-filters"},
      {infer + "--rejuvenate sometimes", "--rejuvenate"},
      {infer + "--particle-estimate counts", "--particle-estimate"},
      {bench + "--particle-estimate counts", "--particle-estimate"},
      {bench + "--particle-filters none", "--particle-filters"},
      {bench + "--particles 0", "--particles"},
      {bench + "--seeds 0", "--seeds"},
      {bench + "--ess-threshold nan", "--ess-threshold"},
  };
  for (const auto& c : cases) {
    auto r = testing::run(c.cmd);
    EXPECT_EQ(r.status, 2) << c.cmd << "\n" << r.out;
    EXPECT_TRUE(contains(r.out, c.option)) << c.cmd << "\n" << r.out;
  }
  // A bench option given to the evaluation subcommand is named as such.
  auto r = testing::run(clips_binary() + " bench --jobs 2 particles --dataset " + examples_dkg());
  EXPECT_NE(r.status, 0);
  EXPECT_TRUE(contains(r.out, "not of `clips bench particles`")) << r.out;
}

TEST(ParticleCli, InferWithParticlesReportsAProperPosterior) {
  auto r = testing::run(clips_binary() + " infer --dataset " + examples_dkg() +
                        " --plan e1.1.keys --particles 64 --particle-seed 3 --json 2>/dev/null");
  ASSERT_EQ(r.status, 0) << r.out;
  const auto j = nlohmann::json::parse(r.out);
  EXPECT_EQ(j["particles"], 64);
  for (const auto& st : j["steps"]) {
    double s = 0;
    for (double p : testing::goal_probabilities(st["posterior"])) s += p;
    EXPECT_NEAR(s, 1.0, 1e-9);
  }
  // The same seed gives the same output.
  auto again = testing::run(clips_binary() + " infer --dataset " + examples_dkg() +
                            " --plan e1.1.keys --particles 64 --particle-seed 3 --json 2>/dev/null");
  // (Every field of every step but its wall time.)
  auto untimed = [](nlohmann::json steps) {
    for (auto& st : steps) st.erase("seconds");
    return steps;
  };
  EXPECT_EQ(untimed(nlohmann::json::parse(again.out)["steps"]), untimed(j["steps"]));
  auto help = testing::run(clips_binary() + " infer --help");
  for (const char* o : {"--particles", "--particle-seed", "--ess-threshold", "--rejuvenation-moves",
                        "--particle-filters", "--rejuvenate", "--particle-estimate"})
    EXPECT_TRUE(contains(help.out, o)) << o;
}

TEST(ParticleCli, BenchParticlesWritesTheComparison) {
  testing::TempDir dir("bench-particles");
  const std::string out = dir.str() + "/eval.json";
  auto r = testing::run(clips_binary() + " bench particles --dataset " + examples_dkg() +
                        " --plans e1.1.keys,e2.1.doors --particles 8,32 --seeds 2 --particle-estimate weights --no-progress --out " +
                        out);
  ASSERT_EQ(r.status, 0) << r.out;
  EXPECT_TRUE(contains(r.out, "TV final")) << r.out;
  std::ifstream f(out);
  const auto j = nlohmann::json::parse(f);
  ASSERT_EQ(j["summary"].size(), 2u);
  EXPECT_EQ(j["plans"], 2);
  // The report names the settings it was made with.
  EXPECT_EQ(j["settings"]["particle_estimate"], "weights");
  EXPECT_EQ(j["settings"]["ess_threshold"], "0.5");
  EXPECT_EQ(j["settings"]["particle_filters"], "all");
  EXPECT_TRUE(contains(r.out, "particle_estimate weights")) << r.out;
  EXPECT_EQ(j["runs"].size(), 2u * 2u * 2u);  // plans x counts x seeds
  for (const auto& s : j["summary"]) {
    EXPECT_EQ(s["runs"], 4);
    EXPECT_GE(s["tv_final"]["max"].get<double>(), s["tv_final"]["median"].get<double>());
    EXPECT_LE(s["tv_final"]["max"].get<double>(), 1.0);
    EXPECT_GT(s["time_ratio"].get<double>(), 0.0);
  }
}

}  // namespace
}  // namespace clips::eval
