// The words people use on a map, read by `clips infer` and acted on by
// `clips assist`, on the repo's warehouse grid (data/datasets/warehouse,
// problem 1: cans can1 red, can2 blue, can3 green; shelves 1-3). The
// sentences are this test's own, not the dataset's instructions.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <map>
#include <string>

#include <nlohmann/json.hpp>

#include "eval/support.hpp"

namespace clips::eval {
namespace {

using testing::clips_binary;
using testing::contains;
using testing::run;
using testing::TempDir;

std::string warehouse() { return std::string(CLIPS_SOURCE_DIR) + "/data/datasets/warehouse"; }
// `s` as one single-quoted shell word.
std::string sq(const std::string& s) {
  std::string out = "'";
  for (char c : s) out += c == '\'' ? std::string("'\\''") : std::string(1, c);
  return out + "'";
}

// The goal posterior after the last step of a `clips infer --json` command,
// by goal name.
std::map<std::string, double> last_posterior(const std::string& cmd) {
  const auto r = run(cmd);
  EXPECT_EQ(r.status, 0) << cmd << "\n" << r.out;
  std::map<std::string, double> p;
  if (r.status != 0) return p;
  const auto j = nlohmann::json::parse(r.out);
  for (const auto& g : j.at("steps").back().at("posterior").at("goals")) p[g.at("goal")] = g.at("p").get<double>();
  return p;
}

// The same on problem 1 for an utterance (language alone unless `modality`
// says otherwise).
std::map<std::string, double> posterior(const std::string& utterance, const std::string& actions = "",
                                        int step = 0, const std::string& modality = "lang_only") {
  std::string cmd = clips_binary() + " infer --json --dataset " + warehouse() + " --problem 1 --modalities " + modality +
                    " --utterance " + sq(utterance);
  if (!actions.empty()) cmd += " --actions " + sq(actions) + " --utterance-step " + std::to_string(step);
  return last_posterior(cmd);
}

double green(const std::map<std::string, double>& p) {
  return p.at("red-green-cans-shelf2") + p.at("small-box-green-can-shelf2");
}

// "shelf 3", "the third shelf": the number tells the shelves apart. Only
// blue-can-big-box-shelf3 fills shelf 3; without reading the number the
// goal statement leaves it 0.18, below the two can goals.
TEST(MapWords, NumberedShelvesAreToldApartByTheirNumber) {
  for (const char* u : {"I want to fill shelf 3.", "I want to fill the third shelf.", "I need shelf number three filled."}) {
    const auto p = posterior(u);
    ASSERT_FALSE(p.empty());
    const double shelf3 = p.at("blue-can-big-box-shelf3");
    for (const auto& [goal, q] : p) {
      if (goal != "blue-can-big-box-shelf3") {
        EXPECT_GT(shelf3, q + 0.1) << u << ": " << goal;
      }
    }
  }
  const auto one = posterior("I want to fill shelf 1.");
  ASSERT_FALSE(one.empty());
  EXPECT_GT(one.at("red-blue-cans-shelf1"), 0.6);
}

// A number said after a place's noun is its number whatever word follows,
// unless that word names one of the domain's kinds, which the number then
// counts: "shelf three needs sorting out" reads as "shelf 3 needs ...", but
// "I need two cans" asks for two cans, not for shelf 2's.
TEST(MapWords, ANumberAfterAPlaceIsItsNumberUnlessItCountsAKind) {
  const auto words = posterior("Shelf three needs sorting out.");
  const auto digits = posterior("Shelf 3 needs sorting out.");
  ASSERT_FALSE(words.empty());
  ASSERT_EQ(words.size(), digits.size());
  for (const auto& [goal, q] : digits) EXPECT_NEAR(words.at(goal), q, 1e-6) << goal;
  EXPECT_GT(words.at("blue-can-big-box-shelf3"), 0.5);
  const auto two = posterior("I need two cans.");
  ASSERT_FALSE(two.empty());
  EXPECT_GT(two.at("red-blue-cans-shelf1") + two.at("red-green-cans-shelf2"), 0.9);
  EXPECT_LT(two.at("red-green-cans-shelf2"), 0.5);
}

// "not the green one" is not a request for the green can: the goals with a
// green can keep less than half the posterior, where the same request
// without "not" gives them nearly all of it.
TEST(MapWords, ANegatedColourIsNotAskedFor) {
  const auto asked = posterior("Please bring me a can, the green one.");
  const auto refused = posterior("Please bring me a can, but not the green one.");
  ASSERT_FALSE(asked.empty());
  ASSERT_FALSE(refused.empty());
  EXPECT_GT(green(asked), 0.8);
  EXPECT_LT(green(refused), 0.5);
  EXPECT_LT(green(refused), green(asked) - 0.35);
}

// Right after the human picked up a can (can2, the only blue one), "another
// one of these" is read as "another can, not the blue one": the two
// sentences give the same posterior.
TEST(MapWords, TheseAfterAPickupNamesThePickedUpKind) {
  const std::string acts =
      "(up human c4-4 c4-3) (wait robot) (up human c4-3 c4-2) (wait robot) (up human c4-2 c4-1) (wait robot) "
      "(left human c4-1 c3-1) (wait robot) (pickup human can2 c3-1)";
  const auto these = posterior("Could you fetch me another one of these?", acts, 9);
  const auto can = posterior("Could you fetch me another can, not the blue one?", acts, 9);
  ASSERT_FALSE(these.empty());
  ASSERT_EQ(these.size(), can.size());
  for (const auto& [goal, q] : can) EXPECT_NEAR(these.at(goal), q, 1e-6) << goal;
}

// Asked outright for the red can, which both likely goals need, the robot
// goes for it rather than waiting while the human walks: the decision says
// it does what was asked.
TEST(MapWords, AskedForTheRedCanTheRobotSetsOff) {
  const std::string cmd = clips_binary() + " assist --json --explain --dataset " + warehouse() +
                          " --problem 1 --actions '(up human c4-4 c4-3)' --utterance-step 1 --utterance " +
                          sq("Could you bring me the red can?");
  const auto r = run(cmd);
  ASSERT_EQ(r.status, 0) << r.out;
  const auto j = nlohmann::json::parse(r.out);
  const std::string action = j.at("action").get<std::string>();
  EXPECT_NE(action, "(wait robot)");
  EXPECT_TRUE(contains(action, "robot")) << action;
  const auto& decision = j.at("decision");
  EXPECT_TRUE(decision.at("followed_request").get<bool>()) << r.out;
  EXPECT_TRUE(contains(decision.at("reason").get<std::string>(), "doing what was asked")) << r.out;
  // The text form says the same reason.
  const auto text = run(clips_binary() + " assist --explain --dataset " + warehouse() +
                        " --problem 1 --actions '(up human c4-4 c4-3)' --utterance-step 1 --utterance " +
                        sq("Could you bring me the red can?"));
  EXPECT_TRUE(contains(text.out, "why: doing what was asked")) << text.out;
}

// The human stands beside the blue can (c3-1) and the robot is six steps
// away; the cheapest joint plan has the human pick it up. Asked for it, the
// robot still sets off: whether a request makes a likely goal costlier is
// judged by the principal's effort, which the fetch spares.
TEST(MapWords, AFetchTheHumanCouldMakeIsStillDoneWhenAsked) {
  const std::string cmd = clips_binary() + " assist --json --explain --dataset " + warehouse() +
                          " --problem 1 --actions '(up human c4-4 c4-3) (wait robot) (up human c4-3 c4-2) (wait robot) "
                          "(up human c4-2 c4-1)' --utterance-step 5 --utterance " +
                          sq("Could you get me the blue can?");
  const auto r = run(cmd);
  ASSERT_EQ(r.status, 0) << r.out;
  const auto j = nlohmann::json::parse(r.out);
  EXPECT_EQ(j.at("action").get<std::string>(), "(up robot c4-6 c4-5)") << r.out;
  EXPECT_TRUE(j.at("decision").at("followed_request").get<bool>()) << r.out;
}

// The robot has fetched the red can and stands with it beside the human at
// shelf 1. Putting it there itself is the cheapest joint plan, but the human
// says they will shelve it and asks for it: the robot hands it over. (The
// request is read off a plan in which the principal keeps the goal's last
// steps, and a step that gives the principal something may leave them one
// more action of their own.)
TEST(MapWords, AskedToHandSomethingOverTheRobotDoesNotShelveIt) {
  const std::string actions =
      "(left human c4-4 c3-4) (up robot c4-6 c4-5) (left human c3-4 c2-4) (up robot c4-5 c4-4) "
      "(left human c2-4 c1-4) (up robot c4-4 c4-3) (wait human) (up robot c4-3 c4-2) (wait human) "
      "(up robot c4-2 c4-1) (wait human) (left robot c4-1 c3-1) (wait human) (left robot c3-1 c2-1) (wait human) "
      "(left robot c2-1 c1-1) (wait human) (pickup robot can1 c1-1) (wait human) (down robot c1-1 c1-2) "
      "(wait human) (down robot c1-2 c1-3) (wait human) (down robot c1-3 c1-4) (wait human)";
  const std::string cmd = clips_binary() + " assist --json --explain --dataset " + warehouse() +
                          " --problem 1 --actions " + sq(actions) + " --utterance-step 25 --utterance " +
                          sq("I'm putting the red can on shelf 1 myself, so hand it to me.");
  const auto r = run(cmd);
  ASSERT_EQ(r.status, 0) << r.out;
  const auto j = nlohmann::json::parse(r.out);
  EXPECT_EQ(j.at("action").get<std::string>(), "(handover robot human can1 c1-4)") << r.out;
  EXPECT_TRUE(j.at("decision").at("followed_request").get<bool>()) << r.out;
  // The reason says what decided: the human's own step after it was allowed.
  EXPECT_TRUE(contains(j.at("decision").at("reason").get<std::string>(), "but by a step of the principal's own"))
      << r.out;
}

// Problem 3: bag1 up the right-hand aisle, bag2 in the bottom-left corner,
// the jars on the left. For white-bags-shelf2 (bag1 and bag2 to shelf 2) the
// cheaper order fetches bag2 first, yet a human walking right towards bag1
// is making progress on that goal; walking right is progress towards no jar.
// With the pack's progress share those steps count less against the bags
// goal than against the jars goal; without it (0) the two fall alike.
TEST(MapWords, AWalkTowardsAGoalsThingCountsLessAgainstItThanAWalkAway) {
  TempDir copy("progress-share");
  const auto bare = copy.path / "warehouse";
  std::filesystem::copy(warehouse(), bare, std::filesystem::copy_options::recursive);
  {
    auto pack = nlohmann::json::parse(std::ifstream(bare / "pack.json"));
    pack["inference"]["progress_share"] = 0;
    std::ofstream(bare / "pack.json") << pack.dump(2);
  }
  auto walk = [&](const std::string& dataset) {
    return last_posterior(clips_binary() + " infer --json --dataset " + dataset +
                          " --problem 3 --modalities action_only --actions " +
                          sq("(right human c4-5 c5-5) (wait robot) (right human c5-5 c6-5)"));
  };
  const auto with = walk(warehouse()), without = walk(bare.string());
  ASSERT_FALSE(with.empty());
  ASSERT_FALSE(without.empty());
  EXPECT_GT(with.at("white-bags-shelf2"), 2 * with.at("yellow-jars-shelf1"));
  EXPECT_LT(without.at("white-bags-shelf2"), 1.5 * without.at("yellow-jars-shelf1"));
  EXPECT_GT(with.at("white-bags-shelf2"), 2 * without.at("white-bags-shelf2"));
}

// In the assistance episode the simulated human follows its recorded plan,
// in which the robot fetches what was asked although the human could have
// (the bench's "requested" column names it). The robot doing its recorded
// part does not cost it the human's trust, so the request gets done.
TEST(MapWords, WhatWasAskedIsDoneInTheBenchsEpisode) {
  TempDir out("map-words-bench");
  const std::string cmd = clips_binary() + " bench --no-progress --methods clips --dataset " + warehouse() +
                          " --plans 7.2.green-crate-small-bag-shelf2 --out " + out.str();
  const auto r = run(cmd);
  ASSERT_EQ(r.status, 0) << r.out;
  std::ifstream in(out.path / "results.csv");
  std::string header, row;
  ASSERT_TRUE(std::getline(in, header) && std::getline(in, row)) << r.out;
  // request_done is the last column; precision: the robot's option was bag2.
  EXPECT_EQ(row.substr(row.rfind(',') + 1), "1") << row;
  EXPECT_TRUE(contains(row, ",\"bag2=1\",")) << row;
}

}  // namespace
}  // namespace clips::eval
