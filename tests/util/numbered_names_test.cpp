// Numbered names: which names people tell apart by their number, and the
// mark that makes the number a word of its own for the embedded model.
#include "util/numbered_names.hpp"

#include <gtest/gtest.h>

#include <string>
#include <vector>

namespace clips::util {
namespace {

TEST(NumberedNames, OnlyAStemSharedByTwoNamesIsNumbered) {
  const std::vector<std::string> names = {"shelf3", "shelf1", "bed-2", "bed-1", "robot", "can1", "c3-4", "x", "12"};
  // can1 is alone: "the can" names it; c3-4 ends in a number after a digit.
  EXPECT_EQ(numbered_names(names), (std::vector<std::string>{"bed-1", "bed-2", "shelf1", "shelf3"}));
  EXPECT_TRUE(numbered_names({"door1"}).empty());
  EXPECT_TRUE(numbered_names({}).empty());
}

TEST(NumberedNames, TheMarkSeparatesStemAndNumber) {
  EXPECT_EQ(number_marked("shelf3"), "shelf#3");
  EXPECT_EQ(number_marked("bed-12"), "bed#12");
  EXPECT_EQ(number_marked("shelf"), "shelf");
  EXPECT_EQ(number_marked("c3-4"), "c3-4");
  EXPECT_EQ(number_marked("42"), "42");
}

TEST(NumberedNames, OnlyWholeNamesInACommandAreMarked) {
  const std::vector<std::string> names = {"shelf1", "shelf3"};
  EXPECT_EQ(mark_numbered("(put you ?can1 shelf3) where (to ?can1 shelf1)", names),
            "(put you ?can1 shelf#3) where (to ?can1 shelf#1)");
  // shelf30 and ?shelf3 are other words.
  EXPECT_EQ(mark_numbered("(put you can1 shelf30) (go ?shelf3)", names), "(put you can1 shelf30) (go ?shelf3)");
  EXPECT_EQ(mark_numbered("(put you can1 shelf3)", {}), "(put you can1 shelf3)");
}

}  // namespace
}  // namespace clips::util
