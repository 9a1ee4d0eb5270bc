// Noun-less deixis: the words that stand for a kind are replaced by its noun
// before the language model reads them (language/deixis.hpp).
#include "language/deixis.hpp"

#include <gtest/gtest.h>

namespace clips::language {
namespace {

const KindNoun kCan{"can", "cans"};

TEST(Deixis, KindWordsBecomeTheNoun) {
  EXPECT_EQ(resolve_deixis("Could you fetch me another one of these?", kCan), "Could you fetch me another can?");
  EXPECT_EQ(resolve_deixis("Grab one more of those, please.", kCan), "Grab one more can, please.");
  EXPECT_EQ(resolve_deixis("I need two more of them.", kCan), "I need two more cans.");
  EXPECT_EQ(resolve_deixis("Can you get another one?", kCan), "Can you get another can?");
  EXPECT_EQ(resolve_deixis("Bring me one more.", kCan), "Bring me one more can.");
  EXPECT_EQ(resolve_deixis("ANOTHER ONE OF THESE!", kCan), "ANOTHER can!");
}

TEST(Deixis, OtherWordsAreLeftAsTheyAre) {
  // "another" before a noun already names the kind; "this" alone may point
  // at anything; no kind, no change.
  EXPECT_EQ(resolve_deixis("Could you fetch another bottle?", kCan), "Could you fetch another bottle?");
  EXPECT_EQ(resolve_deixis("Put this on shelf 2.", kCan), "Put this on shelf 2.");
  EXPECT_EQ(resolve_deixis("Could you fetch me another one of these?", KindNoun{}),
            "Could you fetch me another one of these?");
  EXPECT_EQ(resolve_deixis("", kCan), "");
}

TEST(Deixis, AnotherOneIsNotTheOneTheSpeakerHad) {
  // Given a quality only the speaker's own object has, the resolved words
  // say it is not that one; nothing resolved, nothing added.
  EXPECT_EQ(resolve_deixis("Could you fetch me another one of these?", kCan, "blue"),
            "Could you fetch me another can, not the blue one?");
  EXPECT_EQ(resolve_deixis("One more of those for bed two, please.  ", kCan, "orange"),
            "One more can for bed two, please, not the orange one.");
  EXPECT_EQ(resolve_deixis("Bring me one more", kCan, "red"), "Bring me one more can, not the red one");
  EXPECT_EQ(resolve_deixis("Could you fetch another bottle?", kCan, "blue"), "Could you fetch another bottle?");
  EXPECT_EQ(resolve_deixis("Grab one more of those, please.", kCan, ""), "Grab one more can, please.");
}

TEST(Deixis, ATypeNameIsSaidAsWords) {
  // A type's name is read as the noun people say, with its plural.
  const KindNoun box = kind_noun("box");
  EXPECT_EQ(box.singular, "box");
  EXPECT_EQ(box.plural, "boxes");
  const KindNoun cup = kind_noun("coffee_cup");
  EXPECT_EQ(cup.singular, "coffee cup");
  EXPECT_EQ(cup.plural, "coffee cups");
  EXPECT_TRUE(kind_noun("--").singular.empty());
}

}  // namespace
}  // namespace clips::language
