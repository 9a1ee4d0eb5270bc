// One bad plan file in a dataset: commands on the other plans run, the bad
// plan's own command fails naming its file, and `validate` lists it.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>

#include "eval/support.hpp"

namespace clips::eval {
namespace {

using testing::clips_binary;
using testing::contains;
using testing::run;

struct BrokenCopy : testing::ExamplesCopy {
  BrokenCopy() : ExamplesCopy("broken-plan") {
    std::ofstream(file("plans/observed/e1.2.keys.pddl")) << "(up human)\n; Can you help\n(wait robot)\n; me?\n";
  }
};

TEST(CliBrokenPlan, OtherPlansStillRun) {
  BrokenCopy c;
  auto r = run(clips_binary() + " infer --dataset " + c.ds + " --plan e1.1.keys --json");
  EXPECT_EQ(r.status, 0) << r.out;
  r = run(clips_binary() + " show --dataset " + c.ds + " --plan e2.2.keys --step 0");
  EXPECT_EQ(r.status, 0) << r.out;
  r = run(clips_binary() + " plan --dataset " + c.ds + " --problem e1");
  EXPECT_EQ(r.status, 0) << r.out;
}

TEST(CliBrokenPlan, TheBadPlanNamesItsFile) {
  BrokenCopy c;
  auto r = run(clips_binary() + " infer --dataset " + c.ds + " --plan e1.2.keys");
  EXPECT_EQ(r.status, 3) << r.out;  // an input error
  EXPECT_TRUE(contains(r.out, "plans/observed/e1.2.keys.pddl")) << r.out;
}

TEST(CliBrokenPlan, ValidateListsTheBadFile) {
  BrokenCopy c;
  auto r = run(clips_binary() + " validate --dataset " + c.ds);
  EXPECT_EQ(r.status, 1) << r.out;
  EXPECT_TRUE(contains(r.out, "FAIL  e1.2.keys")) << r.out;
  EXPECT_TRUE(contains(r.out, "plans/observed/e1.2.keys.pddl")) << r.out;
  EXPECT_TRUE(contains(r.out, "ok    e1.1.keys")) << r.out;
  EXPECT_TRUE(contains(r.out, "validated 4 plans, 1 failed")) << r.out;
}

}  // namespace
}  // namespace clips::eval
