// issue 63: the CLI's choice flags list and take the names of the one name
// tables (util/choices.hpp) compiled into this test as into the binary.
#include <gtest/gtest.h>

#include <string>

#include "data/dataset.hpp"
#include "domains/pack.hpp"
#include "engine/methods.hpp"
#include "eval/choices.hpp"
#include "eval/methods.hpp"
#include "eval/support.hpp"
#include "inference/belief.hpp"
#include "language/listener.hpp"
#include "search/planners.hpp"
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

// The tables that were string lists in the subcommands (speaker plans, the
// planner, the bench's assistance set, the language model): each flag's help
// lists its table's names with their help, the catalogue (Python's choices(),
// docs/cli.md's table) holds the table, and a bad name is a usage error
// (status 2) that lists the valid ones.
template <typename V>
void expect_flag_reads(const std::string& subcommand, const std::string& flag, const std::string& id,
                       const util::Choices<V>& table, const std::string& rest = "") {
  const auto help = run(clips_binary() + " " + subcommand + " --help");
  ASSERT_EQ(help.status, 0) << help.out;
  EXPECT_TRUE(contains(help.out, flag)) << help.out;
  for (const auto& c : table.entries())
    EXPECT_TRUE(contains(help.out, c.name + " (" + c.help.substr(0, 20))) << flag << " " << c.name << "\n" << help.out;
  bool listed = false;
  for (const auto& [kind, info] : choice_catalogue())
    if (kind == id) listed = info.names() == table.names();
  EXPECT_TRUE(listed) << id;
  const auto bad = run(clips_binary() + " " + subcommand + " " + flag + " oracle " + rest);
  EXPECT_EQ(bad.status, 2) << flag << "\n" << bad.out;
  EXPECT_TRUE(contains(bad.out, "oracle")) << bad.out;
  for (const auto& n : table.names()) EXPECT_TRUE(contains(bad.out, n)) << flag << " " << n << "\n" << bad.out;
}

TEST(ChoicesCli, EveryChoiceFlagReadsItsTable) {
  expect_flag_reads("infer", "--speaker-plans", "speaker_plans", domains::speaker_plans_choices(), "--plan x");
  expect_flag_reads("infer", "--lm", "lm", language::language_model_choices(), "--plan x");
  expect_flag_reads("plan", "--planner", "planner", search::planner_choices(), "--problem x");
  expect_flag_reads("bench", "--assist", "bench_assist", assistance_set_choices());
}

// --condition is a pack's plan tag (pack.json plan_tags): the CLI knows no
// tag of its own, and an unknown one is a usage error listing the pack's.
TEST(ChoicesCli, TheConditionIsOneOfThePacksPlanTags) {
  const std::string adhoc = " --problem e1 --actions \"(left human)\" --utterance \"the red key\"";
  const auto tags = data::Dataset::load_problems(testing::examples_dkg()).pack().spec().plan_tags;
  ASSERT_GE(tags.size(), 2u);
  const auto r = run(clips_binary() + " infer --dataset " + testing::examples_dkg() + adhoc + " --condition trees");
  EXPECT_EQ(r.status, 2) << r.out;
  EXPECT_TRUE(contains(r.out, "unknown plan tag 'trees'")) << r.out;
  for (const auto& t : tags) EXPECT_TRUE(contains(r.out, t)) << t << "\n" << r.out;

  const std::string garden = paths::source_dir() + "/tests/fixtures/garden";
  const auto g = run(clips_binary() + " infer --dataset " + garden + " --problem 1 --utterance \"plant it\" --condition " +
                     tags.front());
  EXPECT_EQ(g.status, 2) << g.out;
  EXPECT_TRUE(contains(g.out, "declares no plan tags")) << g.out;

  const auto p = run(clips_binary() + " infer --dataset " + testing::examples_dkg() + " --plan e1.1.keys --condition " +
                     tags.front());
  EXPECT_EQ(p.status, 2) << p.out;
  EXPECT_TRUE(contains(p.out, "--condition goes with --problem")) << p.out;
}

}  // namespace
}  // namespace clips::eval
