// Unsatisfiable goal recognition for Doors-Keys-Gems.
#include <gtest/gtest.h>

#include "domains/dkg/dkg_goals.hpp"

using clips::domains::dkg::dkg_goal_unsatisfiable;

TEST(DkgGoals, UsedKeysCannotBeHeld) {
  EXPECT_TRUE(dkg_goal_unsatisfiable("(and (has robot key1) (unlocked-by robot door1) (unlocked-with key1 door1))"));
  EXPECT_TRUE(dkg_goal_unsatisfiable(
      "(exists (?key1 - key ?door1 - door) (and (has robot ?key1) (unlocked-with ?key1 ?door1) (not (= ?key1 ?door1))))"));
  EXPECT_FALSE(dkg_goal_unsatisfiable("(and (has robot key2) (unlocked-with key1 door1))"));
}

TEST(DkgGoals, OneHolderOneKeyPerDoorOneDoorPerKey) {
  EXPECT_TRUE(dkg_goal_unsatisfiable("(and (has robot key3) (has human key3))"));
  EXPECT_TRUE(dkg_goal_unsatisfiable("(and (unlocked-with key2 door1) (unlocked-with key3 door1))"));
  EXPECT_TRUE(dkg_goal_unsatisfiable("(and (unlocked-with key2 door1) (unlocked-with key2 door2))"));
  // Variables only count as different objects when declared unequal.
  EXPECT_FALSE(dkg_goal_unsatisfiable(
      "(exists (?key2 - key ?key3 - key) (and (unlocked-with ?key2 door1) (unlocked-with ?key3 door1)))"));
  EXPECT_TRUE(dkg_goal_unsatisfiable(
      "(exists (?key2 - key ?key3 - key) (and (unlocked-with ?key2 door1) (unlocked-with ?key3 door1) "
      "(not (= ?key2 ?key3))))"));
}

TEST(DkgGoals, SatisfiableAndNonConjunctiveGoalsAreLeftAlone) {
  EXPECT_FALSE(dkg_goal_unsatisfiable("(has human gem1)"));
  EXPECT_FALSE(dkg_goal_unsatisfiable("(and (has human key1) (pickedup-by robot key1) (has human key2))"));
  EXPECT_FALSE(dkg_goal_unsatisfiable("(or (has robot key1) (has human key1))"));
  EXPECT_FALSE(dkg_goal_unsatisfiable("(unbalanced"));
}
