// `clips generate` on the command line: the dataset it writes is what
// validate and infer read, the same arguments give the same bytes, and bad
// values are usage errors naming the flag.
#include <gtest/gtest.h>

#include <filesystem>
#include <string>
#include <vector>

#include "eval/support.hpp"

namespace clips::eval {
namespace {

using testing::clips_binary;
using testing::contains;
using testing::read_text;
using testing::run;
using testing::TempDir;

namespace fs = std::filesystem;

const std::string kSmall = " generate --size 7x7 --gems 2 --keys 1 --doors 1 --plans 2 -q";

// Every file under `dir`, relative path -> content.
std::map<std::string, std::string> files_of(const fs::path& dir) {
  std::map<std::string, std::string> out;
  for (const auto& e : fs::recursive_directory_iterator(dir))
    if (e.is_regular_file()) out[fs::relative(e.path(), dir).string()] = read_text(e.path());
  return out;
}

TEST(GenerateCli, WritesADatasetTheOtherCommandsReadTheSameEveryTime) {
  TempDir dir("generate-cli");
  const std::string a = (dir.path / "a").string(), b = (dir.path / "b").string(), c = (dir.path / "c").string();
  auto r = run(clips_binary() + kSmall + " --seed 3 --out " + a);
  ASSERT_EQ(r.status, 0) << r.out;
  EXPECT_TRUE(contains(r.out, "wrote 1 problems and 2 plans to " + a)) << r.out;
  r = run(clips_binary() + " validate --dataset " + a);
  EXPECT_EQ(r.status, 0) << r.out;
  EXPECT_TRUE(contains(r.out, "validated 2 plans, 0 failed")) << r.out;
  std::string plan;
  for (const auto& e : fs::directory_iterator(fs::path(a) / "plans" / "observed")) plan = e.path().stem().string();
  r = run(clips_binary() + " infer --dataset " + a + " --plan " + plan);
  EXPECT_EQ(r.status, 0) << r.out;

  ASSERT_EQ(run(clips_binary() + kSmall + " --seed 3 --out " + b).status, 0);
  const auto first = files_of(a);
  EXPECT_EQ(first, files_of(b)) << "same arguments and seed, other bytes";
  EXPECT_TRUE(first.count("problems/1.txt") && first.count("generation.json") && first.count("domain.pddl"));
  ASSERT_EQ(run(clips_binary() + kSmall + " --seed 4 --out " + c).status, 0);
  EXPECT_NE(first, files_of(c));
  EXPECT_TRUE(contains(first.at("generation.json"), "\"max_nodes\": 262144")) << "the budget inference should use";

  // A second run over a dataset needs --force.
  r = run(clips_binary() + kSmall + " --seed 3 --out " + a);
  EXPECT_EQ(r.status, 3) << r.out;
  EXPECT_TRUE(contains(r.out, "--force")) << r.out;
  EXPECT_EQ(run(clips_binary() + kSmall + " --seed 3 --force --out " + a).status, 0);
}

TEST(GenerateCli, BadValuesAreUsageErrorsNamingTheFlag) {
  TempDir dir("generate-bad");
  const std::string out = " --out " + (dir.path / "x").string();
  const std::vector<std::pair<std::string, std::string>> cases = {
      {" --size 7", "--size"},        {" --size 7x", "--size"},           {" --size axb", "--size"},
      {" --gems 0", "--gems"},        {" --keys -1", "--keys"},           {" --doors x", "--doors"},
      {" --plans 0", "--plans"},      {" --problems -2", "--problems"},   {" --seed -1", "--seed"},
      {" --temperature 0", "--temperature"}, {" --temperature hot", "--temperature"}, {" --max-steps 0", "--max-steps"},
      {" --max-nodes 0", "--max-nodes"}, {" --max-nodes many", "--max-nodes"},
  };
  for (const auto& [args, flag] : cases) {
    auto r = run(clips_binary() + " generate" + args + out);
    EXPECT_EQ(r.status, 2) << args << "\n" << r.out;
    EXPECT_TRUE(contains(r.out, flag)) << args << "\n" << r.out;
  }
  auto r = run(clips_binary() + " generate --size 7x7");
  EXPECT_EQ(r.status, 2) << r.out;
  EXPECT_TRUE(contains(r.out, "--out")) << r.out;
}

TEST(GenerateCli, ImpossibleParametersSayWhy) {
  TempDir dir("generate-impossible");
  const std::string out = " --out " + (dir.path / "x").string();
  auto r = run(clips_binary() + " generate --size 3x3 --gems 4 --keys 5 --doors 0" + out);
  EXPECT_EQ(r.status, 3) << r.out;
  EXPECT_TRUE(contains(r.out, "need 11 cells, but a 3x3 map has only 9")) << r.out;
  r = run(clips_binary() + " generate --gems 65" + out);
  EXPECT_EQ(r.status, 3) << r.out;
  EXPECT_TRUE(contains(r.out, "--gems 65")) << r.out;
  r = run(clips_binary() + " generate --size 41x41" + out);
  EXPECT_EQ(r.status, 3) << r.out;
  EXPECT_TRUE(contains(r.out, "3 to 40 cells")) << r.out;
  r = run(clips_binary() + " generate --domain virtual-home" + out);
  EXPECT_EQ(r.status, 3) << r.out;
  EXPECT_TRUE(contains(r.out, "cannot generate problems")) << r.out;
  EXPECT_FALSE(fs::exists(dir.path / "x")) << "nothing is written on error";
}

}  // namespace
}  // namespace clips::eval
