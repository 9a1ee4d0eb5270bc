#include "commands/fewshot_test.hpp"

namespace clips::commands {
namespace fewshot_test {
TEST(FewShotFile, SharedReferenceFileLoadsAndAgrees) {
  const std::string shared = CLIPS_SOURCE_DIR "/../shared/reference/fewshot-examples.tsv";
  if (!std::filesystem::exists(shared)) GTEST_SKIP() << "shared reference not present";
  const auto theirs = load_fewshot_examples(shared);
  const auto ours = load_fewshot_examples(kTsv);
  ASSERT_EQ(theirs.size(), ours.size());
  for (size_t i = 0; i < ours.size(); ++i) {
    EXPECT_EQ(theirs[i].command, ours[i].command);
    EXPECT_EQ(theirs[i].utterance, ours[i].utterance);
  }
}

}  // namespace fewshot_test

}  // namespace clips::commands
