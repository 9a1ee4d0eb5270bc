// issue 63: the CLI's choice flags list and take the names of the one name
// tables (util/choices.hpp) compiled into this test as into the binary.
#include <gtest/gtest.h>

#include <string>

#include "engine/methods.hpp"
#include "eval/methods.hpp"
#include "eval/support.hpp"
#include "inference/belief.hpp"
#include "test_paths.hpp"

namespace clips::eval {
namespace {

using testing::clips_binary;
using testing::contains;
using testing::run;

TEST(ChoicesCli, FlagsListTheTablesNamesWithTheirHelp) {
  const auto assist = run(clips_binary() + " assist --help");
  ASSERT_EQ(assist.status, 0) << assist.out;
  for (const auto& c : assist_policy_choices().entries())
    EXPECT_TRUE(contains(assist.out, c.name + " (" + c.help.substr(0, 20))) << c.name << "\n" << assist.out;
  for (const auto& n : domains::literal_method_choices().names()) EXPECT_TRUE(contains(assist.out, n)) << n;
  const auto infer = run(clips_binary() + " infer --help");
  for (const auto& n : inference::assistant_turns_choices().names()) EXPECT_TRUE(contains(infer.out, n)) << n;
  for (const auto& n : engine::posterior_method_names()) EXPECT_TRUE(contains(infer.out, n)) << n;
}

TEST(ChoicesCli, ABadNameIsRefusedWithTheValidOnes) {
  const auto r = run(clips_binary() + " assist --assist oracle --plan x");
  EXPECT_EQ(r.status, 2) << r.out;
  EXPECT_TRUE(contains(r.out, "qmdp_offline")) << r.out;
  const auto m = run(clips_binary() + " infer --modalities oracle --plan x");
  EXPECT_EQ(m.status, 2) << m.out;
  EXPECT_TRUE(contains(m.out, "unknown method 'oracle' (known: clips, lang_only, action_only, literal")) << m.out;
}

}  // namespace
}  // namespace clips::eval
