#include "commands/language_config.hpp"

#include <gtest/gtest.h>

#include "paper_languages.hpp"
#include "util/error.hpp"

namespace clips::commands {
namespace {

TEST(LanguageConfig, PaperRuleFlagsParse) {
  const auto c = parse_language_config(
      R"({"domain": "d", "salient_actions": [{"action": "pickup", "focal_arg": 2}],
          "speaker_actions": "exclude-speaker-only-commands", "exclude_chains": true})",
      "inline.json");
  EXPECT_EQ(c.speaker_actions, SpeakerActionRule::ExcludeSpeakerOnlyCommands);
  EXPECT_TRUE(c.exclude_chains);
  EXPECT_EQ(c.salient_actions.at(0).agent_arg, 1);
  EXPECT_DOUBLE_EQ(c.goal_with_command, 0.5);  // the default
  const auto none = parse_language_config(
      R"({"domain": "d", "salient_actions": [{"action": "pickup", "focal_arg": 2}], "goal_with_command": 0})",
      "inline.json");
  EXPECT_DOUBLE_EQ(none.goal_with_command, 0.0);
}

TEST(LanguageConfig, ErrorsNameFileAndKey) {
  const auto message_of = [](const std::string& json) {
    try {
      parse_language_config(json, "lang.json");
    } catch (const InputError& e) {
      return std::string(e.what());
    }
    return std::string("no error");
  };
  EXPECT_EQ(message_of(R"({"domain": "d"})"), "lang.json: .salient_actions: missing");
  EXPECT_EQ(message_of(R"({"domain": "d", "salient_actions": [{"action": "a", "focal_arg": 0}]})"),
            "lang.json: salient_actions[0].focal_arg: expected an integer >= 1");
  EXPECT_EQ(message_of(R"({"domain": "d", "salient_actions": [{"action": "a", "focal_arg": 2}], "colour": 1})"),
            "lang.json: colour: unknown key");
  EXPECT_EQ(message_of(R"({"domain": "d", "salient_actions": [{"action": "a", "focal_arg": 2}],
                          "printed_form": "fancy"})"),
            "lang.json: printed_form: expected one of: where-clause, qualified-args-only");
  EXPECT_EQ(message_of(R"({"domain": "d", "salient_actions": [{"action": "a", "focal_arg": 2}],
                          "goal_with_command": 1.5})"),
            "lang.json: goal_with_command: expected a number in [0, 1]");
  EXPECT_NE(message_of("{").find("lang.json: invalid JSON"), std::string::npos);
  EXPECT_NE(message_of(R"({"domain": "d", "max_command_actions": 1e999})").find("lang.json: invalid JSON"), std::string::npos);
}

TEST(LanguageConfig, PronounsMapBothWays) {
  const auto c = doors_keys_gems_language();
  EXPECT_EQ(c.to_pronoun("human"), "me");
  EXPECT_EQ(c.to_pronoun("robot"), "you");
  EXPECT_EQ(c.to_pronoun("key1"), "key1");
  EXPECT_EQ(c.to_agent_name("you"), "robot");
  EXPECT_EQ(c.to_agent_name("me"), "human");
}

}  // namespace
}  // namespace clips::commands
