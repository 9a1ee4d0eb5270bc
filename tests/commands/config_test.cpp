#include "language/commands/language_config.hpp"

#include <gtest/gtest.h>

#include "util/error.hpp"

namespace clips::commands {
namespace {

void expect_same(const LanguageConfig& a, const LanguageConfig& b) {
  EXPECT_EQ(a.domain, b.domain);
  ASSERT_EQ(a.salient_actions.size(), b.salient_actions.size());
  for (std::size_t i = 0; i < a.salient_actions.size(); ++i) {
    EXPECT_EQ(a.salient_actions[i].action, b.salient_actions[i].action);
    EXPECT_EQ(a.salient_actions[i].agent_arg, b.salient_actions[i].agent_arg);
    EXPECT_EQ(a.salient_actions[i].focal_arg, b.salient_actions[i].focal_arg);
  }
  EXPECT_EQ(a.qualifier, b.qualifier);
  EXPECT_EQ(a.qualifier_object_arg, b.qualifier_object_arg);
  EXPECT_EQ(a.speaker, b.speaker);
  EXPECT_EQ(a.listener, b.listener);
  EXPECT_EQ(a.speaker_pronoun, b.speaker_pronoun);
  EXPECT_EQ(a.listener_pronoun, b.listener_pronoun);
  EXPECT_EQ(a.max_command_actions, b.max_command_actions);
  EXPECT_EQ(a.max_action_types, b.max_action_types);
  EXPECT_EQ(a.max_qualifier_values_per_action_type, b.max_qualifier_values_per_action_type);
  EXPECT_EQ(a.speaker_actions, b.speaker_actions);
  EXPECT_EQ(a.exclude_chains, b.exclude_chains);
  EXPECT_EQ(a.paper_speaker_actions, b.paper_speaker_actions);
  EXPECT_EQ(a.paper_exclude_chains, b.paper_exclude_chains);
  EXPECT_EQ(a.variable_naming, b.variable_naming);
  EXPECT_EQ(a.printed_form, b.printed_form);
  EXPECT_EQ(a.goal_atoms, b.goal_atoms);
  EXPECT_EQ(a.goal_variables, b.goal_variables);
}

TEST(LanguageConfig, ShippedFilesEqualBuiltIns) {
  expect_same(load_language_config(CLIPS_SOURCE_DIR "/data/domains/doors-keys-gems/language.json"),
              doors_keys_gems_language());
  expect_same(load_language_config(CLIPS_SOURCE_DIR "/data/domains/virtual-home/language.json"),
              virtual_home_language());
}

TEST(LanguageConfig, PaperRuleFlagsParse) {
  const auto c = parse_language_config(
      R"({"domain": "d", "salient_actions": [{"action": "pickup", "focal_arg": 2}],
          "speaker_actions": "exclude-speaker-only-commands", "exclude_chains": true})",
      "inline.json");
  EXPECT_EQ(c.speaker_actions, SpeakerActionRule::ExcludeSpeakerOnlyCommands);
  EXPECT_TRUE(c.exclude_chains);
  EXPECT_EQ(c.salient_actions.at(0).agent_arg, 1);
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
  EXPECT_NE(message_of("{").find("lang.json: invalid JSON"), std::string::npos);
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
