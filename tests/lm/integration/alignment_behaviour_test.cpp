#include "lm/alignment_behaviour_test.hpp"

namespace clips::lm {
namespace alignment_behaviour_test {
// Item 4, C: the copy probability alpha is one parameter shared by all
// colours, so a colour the corpus has rarely ("orange": 21 times, against 292
// for "blue") is copied from the command as readily as a frequent one. Without the
// copy only the contradiction of item 7 tells the keys apart (3.2 and 3.4
// nats when the copy was disabled to check this test; 5.2 and 8.8 with it).
TEST(AlignmentBehaviour, RareColoursAreCopiedAsReadilyAsFrequentOnes) {
  const std::string orange = literal_prompt("(pickup you key1) where (iscolor key1 orange)");
  const std::string blue = literal_prompt("(pickup you key1) where (iscolor key1 blue)");
  const double gap_orange = lead(orange, blue, " Pick up the orange key.\n");
  const double gap_blue = lead(blue, orange, " Pick up the blue key.\n");
  std::printf("[shared copy] orange %.2f, blue %.2f nats\n", gap_orange, gap_blue);
  EXPECT_GT(gap_orange, 4.5);
  EXPECT_GT(gap_blue, 4.5);
  // Rare or frequent, the copied colour tells the keys apart (the rare one
  // even more: the shared residual table already expects "blue" anywhere).
  EXPECT_GT(gap_orange, gap_blue - 1.0);
}

TEST(AlignmentGolden, ScoresMatchTheRecordedOnes) {
  const bool print = std::getenv("CLIPS_GOLDEN_PRINT") != nullptr;
  for (const Golden& g : kGolden) {
    const double s = score(prompt_of(g), g.continuation);
    if (print) std::printf("GOLDEN %.17g  %s | %s\n", s, g.command, g.continuation);
    EXPECT_NEAR(s, g.log_prob, 1e-9) << g.kind << " " << g.command << " /" << g.continuation;
  }
}

}  // namespace alignment_behaviour_test

}  // namespace clips::lm
