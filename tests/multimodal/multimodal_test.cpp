#include "multimodal/multimodal_test.hpp"

namespace clips::multimodal {
namespace multimodal_test {
TEST(MultimodalParse, StrictJson) {
  auto a = parse_multimodal_answer(
      R"J({"goal_probabilities": {"gem1": 0.1, "gem2": 0.1, "gem3": 0.7, "gem4": 0.1}, "actions": ["(down robot)"]})J",
      kGoals);
  EXPECT_NEAR(a.goal_posterior[2], 0.7, 1e-12);
  ASSERT_EQ(a.actions.size(), 1u);
  EXPECT_EQ(a.actions[0], "(down robot)");
  EXPECT_TRUE(a.notes.empty());
}

TEST(MultimodalParse, FencedJsonMissingGoalsAndRenormalisation) {
  auto a = parse_multimodal_answer("```json\n{\"goal_probabilities\": {\"gem3\": 2e-1, \"gem1\": 0.2}, \"actions\": []}\n```",
                                   kGoals);
  EXPECT_NEAR(a.goal_posterior[0], 0.5, 1e-12);
  EXPECT_NEAR(a.goal_posterior[2], 0.5, 1e-12);
  EXPECT_EQ(a.goal_posterior[1], 0);
  EXPECT_EQ(a.notes.size(), 3u);  // gem2, gem4 missing; renormalised
}

TEST(MultimodalParse, ErrorsNameTheField) {
  expect_error("Sure! The goal is gem3.", "not valid JSON");
  expect_error("[1, 2]", "not an object");
  expect_error(R"J({"actions": []})J", "\"goal_probabilities\"");
  expect_error(R"J({"goal_probabilities": [0.5, 0.5], "actions": []})J", "must be an object");
  expect_error(R"J({"goal_probabilities": {"gem9": 1}, "actions": []})J", "unknown goal \"gem9\"");
  expect_error(R"J({"goal_probabilities": {"gem1": "high"}, "actions": []})J", "\"goal_probabilities\".gem1 must be a number");
  expect_error(R"J({"goal_probabilities": {"gem1": 1.5}, "actions": []})J", "in [0, 1]");
  expect_error(R"J({"goal_probabilities": {"gem1": 0}, "actions": []})J", "sum to 0");
  expect_error(R"J({"goal_probabilities": {"gem1": 1}})J", "no \"actions\" field");
  expect_error(R"J({"goal_probabilities": {"gem1": 1}, "actions": "(down robot)"})J", "\"actions\" must be an array");
  expect_error(R"J({"goal_probabilities": {"gem1": 1}, "actions": [3]})J", "\"actions\"[0] must be a string");
}

}  // namespace multimodal_test

}  // namespace clips::multimodal
